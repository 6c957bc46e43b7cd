// What the hybrid mesh workflow hands to the window: the core's result for the open model
// (thesis chapter 5), its mesh with each cell's min dihedral angle as cellQuality, and the
// per-type figures of the dock.
#pragma once

#include "hybrid/hybrid_mesher.h"
#include "hybrid_panel.h"
#include "message.h"
#include "model/model.h"
#include "workflow_job.h"

#include <QMetaType>

#include <memory>

namespace stratamesh {

struct HybridOutcome {
    std::shared_ptr<const Model> input;
    std::shared_ptr<const HybridResult> result;
    HybridParams params;
    HybridStatistics statistics;
    qint64 milliseconds = 0;

    // The result's mesh, sharing its lifetime.
    std::shared_ptr<const VolumeMesh> mesh() const
    {
        if (!result)
            return nullptr;
        return std::shared_ptr<const VolumeMesh>(result, &result->mesh);
    }
};

struct HybridRun {
    using Status = RunStatus;
    Status status = Status::Failed;
    HybridOutcome outcome; // when Done
    Message error;         // when Failed
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::HybridOutcome)
