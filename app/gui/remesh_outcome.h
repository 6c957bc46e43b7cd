// What the remesh workflow hands to the window: the new model, its simplification ledger and
// the Table 4.2 comparison with the input, or why there is none.
#pragma once

#include "message.h"
#include "model/model.h"
#include "model/model_counts.h"
#include "quality/model_comparison.h"
#include "remesh/simplification_ledger.h"
#include "remesh/surface_remesher.h"
#include "workflow_job.h"

#include <QMetaType>

#include <memory>

namespace stratamesh {

struct RemeshOutcome {
    std::shared_ptr<const Model> input; // the model that was remeshed, unchanged
    std::shared_ptr<const Model> output;
    std::shared_ptr<const SimplificationLedger> ledger;
    ModelComparison comparison;
    ModelCounts counts; // of the output, with and without the box
    RemeshParams params;
    int siteCount = 0;
    int initialSiteCount = 0; // asked for; siteCount includes the local refinement
    ValidityReport validity;  // of the output: an invalid result is shown as such
    qint64 milliseconds = 0;
    // For the run's report in a project (the same report as the command line's).
    int refinementRounds = 0;
    int refinementRoundsRun = 0;
    int remainingTargets = 0;
    int sizedSiteCount = 0;
    double smallestCellSize = 0.0;
    int pocketsOpened = 0;
    RemeshTimings timings;
    std::vector<double> energy;
};

struct RemeshRun {
    using Status = RunStatus;
    Status status = Status::Failed;
    RemeshOutcome outcome; // when Done
    Message error;         // when Failed
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::RemeshOutcome)
