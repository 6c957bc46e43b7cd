// A project's run as the remesh workflow shows it, rebuilt from its folder (project_runs.h)
// without the engine: the output model, ledger, validity, timings and Hausdorff distance read
// back, the cheap rows of the comparison measured again on input and output.
#pragma once

#include "project_runs.h"
#include "remesh_outcome.h"

namespace stratamesh {

// Takes the model and ledger out of `read`. FileError naming `reportPath` for a report that
// lacks what the comparison needs.
RemeshOutcome restoredOutcome(std::shared_ptr<const Model> input, const ProjectRun &run,
                              RunRead &read, const QString &reportPath);

} // namespace stratamesh
