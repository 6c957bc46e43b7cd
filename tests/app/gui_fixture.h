// What many GUI tests start from: the bundled sample open in the window, then a remesh of it
// through the Remesh workflow (the engine in its background thread, as a user's click runs it).
#pragma once

#include "main_window.h"
#include "open_workflow.h"
#include "remesh_workflow.h"

#include "remesh/surface_remesher.h"

#include <QSignalSpy>

namespace stratamesh::test {

// The sample model opened and shown; false when it did not open within `timeoutMs`.
inline bool openSample(MainWindow &window, int timeoutMs)
{
    QSignalSpy loaded(window.openWorkflow(), &OpenWorkflow::finished);
    window.openSample();
    return loaded.wait(timeoutMs) && loaded.first().first().toBool();
}

// A remesh of the open model with these parameters, finished and shown; false when it could not
// start, failed, or did not finish within `timeoutMs`.
inline bool remeshOpenModel(MainWindow &window, int sites, int iterations, int timeoutMs)
{
    RemeshParams params;
    params.sites = sites;
    params.iterations = iterations;
    QSignalSpy finished(window.remeshWorkflow(), &RemeshWorkflow::finished);
    if (!window.remeshWorkflow()->start(params))
        return false;
    return finished.wait(timeoutMs) && finished.first().first().toBool();
}

} // namespace stratamesh::test
