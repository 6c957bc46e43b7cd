// What the tetrahedralise workflow hands to the window: TetGen's meshes of the input model and,
// when there is one, of its remesh, under the same switches (thesis §5.2). A side TetGen failed
// on is part of the outcome (its TetgenResult says how), not an error of the run.
#pragma once

#include "message.h"
#include "model/model.h"
#include "volume/tetgen_comparison.h"
#include "workflow_job.h"

#include <QMetaType>

#include <memory>

namespace stratamesh {

struct TetmeshOutcome {
    std::shared_ptr<const Model> input;  // unchanged
    std::shared_ptr<const Model> output; // the remesh; nullptr for an input-only run
    std::shared_ptr<const TetmeshSide> inputSide;
    std::shared_ptr<const TetmeshSide> outputSide; // nullptr for an input-only run
    TetgenParams params;
    qint64 milliseconds = 0;

    // The side's tets, sharing its lifetime; nullptr when there is no side or TetGen failed.
    static std::shared_ptr<const VolumeMesh> meshOf(const std::shared_ptr<const TetmeshSide> &side)
    {
        if (!side || side->result.outcome != TetgenOutcome::Ok)
            return nullptr;
        return std::shared_ptr<const VolumeMesh>(side, &side->result.mesh);
    }
};

struct TetmeshRun {
    using Status = RunStatus;
    Status status = Status::Failed;
    TetmeshOutcome outcome; // when Done
    Message error;          // when Failed
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::TetmeshOutcome)
