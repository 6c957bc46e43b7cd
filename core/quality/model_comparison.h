// Input vs output of a remeshing, as the rows of thesis Table 4.2 (§4.5): sizes, entity counts,
// smallest angle, % of triangles with an angle < 30°, mean quality Q, area, Hausdorff distance in
// % of the bounding-box diagonal, and the timings of sampling and mesh building; plus histograms
// of min angle and Q over the same bins for both sides.
#pragma once

#include "common/progress.h"
#include "model/model.h"
#include "model/model_counts.h"
#include "quality/hausdorff.h"
#include "quality/histogram.h"
#include "quality/mesh_statistics.h"

#include <string>
#include <vector>

namespace stratamesh {

struct ComparisonRow {
    std::string label;      // model name
    std::string resolution; // "Input" or the number of sites
    MeshStatistics mesh;
    EntityCounts counts; // box excluded, as Table 3.1 (thesis Table 4.2 counts components)
    double samplingSeconds = 0.0;
    double meshSeconds = 0.0;
    double hausdorffPctBbox = -1.0; // -1 for the input row
};

struct ModelComparison {
    ComparisonRow input;
    ComparisonRow output;
    HausdorffResult hausdorff;
    Histogram inputMinAngle{minAngleBinEdges()};
    Histogram outputMinAngle{minAngleBinEdges()};
    Histogram inputQuality{qualityBinEdges()};
    Histogram outputQuality{qualityBinEdges()};
};

// Both models need topology (for the counts). Throws InputError otherwise.
ModelComparison compareModels(const Model &input, const Model &output,
                              const HausdorffParams &hausdorff = {},
                              Progress &progress = Progress::none());

// The same with a Hausdorff distance already measured (a saved run's report), so reopening a
// project does not sample both models again.
ModelComparison compareModels(const Model &input, const Model &output,
                              const HausdorffResult &measured);

// Two remeshes of one input side by side (a run compared with another): `first` in the input
// column, `second` in the output column, each with its figures, histograms and Hausdorff distance
// to the input they were both made from; the Hausdorff result kept is the second's. Nothing is
// measured again. Throws InputError when the two were not made from the same input model.
ModelComparison compareRuns(const ModelComparison &first, const ModelComparison &second);

// A plain-text table in the layout of Table 4.2, one line per row (Markdown pipes).
std::string formatTable42(const std::vector<ComparisonRow> &rows);

} // namespace stratamesh
