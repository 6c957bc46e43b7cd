// The "remesh" workflow: remeshAndReview() (as the CLI) on the loaded model in a worker
// thread, reporting progress, cancellable at the engine's next progress tick. The input model is
// shared read-only and never changed; the window only shows the outcome.
#pragma once

#include "remesh_outcome.h"
#include "workflow_job.h"

#include <QFutureWatcher>

#include <memory>

namespace stratamesh {

class RemeshController : public WorkflowJob {
    Q_OBJECT
public:
    explicit RemeshController(QObject *parent = nullptr);
    ~RemeshController() override;

    // Returns immediately; false when busy or without a model.
    bool start(std::shared_ptr<const Model> input, const RemeshParams &params);
    // Engine runs started so far: a reopened project shows its runs without one.
    int runCount() const { return m_runCount; }

signals:
    void succeeded(const stratamesh::RemeshOutcome &outcome);

private:
    void onFinished();

    QFutureWatcher<RemeshRun> m_watcher;
    int m_runCount = 0;
};

} // namespace stratamesh
