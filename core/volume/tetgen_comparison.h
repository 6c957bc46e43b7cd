// Input model vs remeshed model under the same TetGen switches (thesis §5.2: the point of a remesh
// is fewer, better tetrahedra and a mesher that does not fail): each side's outcome, tets per
// region against the B-Rep volumes, and tet quality, for the CLI report and the GUI table.
#pragma once

#include "common/progress.h"
#include "model/model.h"
#include "volume/region_tets.h"
#include "volume/tet_quality.h"
#include "volume/tetgen_runner.h"

#include <vector>

namespace stratamesh {

struct TetmeshSide {
    TetgenResult result;             // mesh.cellQuality holds each tet's min dihedral angle
    VolumeQualityStatistics quality; // zeros unless result.outcome is Ok
    std::vector<RegionTets> regions; // per Model::regions (zeros unless Ok)
    std::vector<double> brepVolumes; // regionVolumes() of the model
};

// runTetgen() then the statistics. Throws Cancelled like runTetgen().
TetmeshSide tetmeshModel(const Model &model, const TetgenParams &params,
                         Progress &progress = Progress::none());

struct TetmeshComparison {
    TetmeshSide input;
    TetmeshSide output;
};

// Both models with the same parameters, the input first (progress 0-0.5, then 0.5-1). A failure
// of one side is a result of that side; the other still runs.
TetmeshComparison compareTetmeshes(const Model &input, const Model &output,
                                   const TetgenParams &params,
                                   Progress &progress = Progress::none());

} // namespace stratamesh
