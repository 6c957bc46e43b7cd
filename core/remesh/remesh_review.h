// The remesh workflow every front end runs (thesis §4.5): remeshModel(), then the comparison
// with the input of Table 4.2 (Hausdorff distance with one sample count for all), and the
// validity of both sides. The CLI writes it as a report, the GUI shows it in its docks.
#pragma once

#include "common/progress.h"
#include "model/validity.h"
#include "quality/model_comparison.h"
#include "remesh/surface_remesher.h"

namespace stratamesh {

// Hausdorff samples per side for a remesh's comparison, the same in the CLI's report and the
// GUI's table.
constexpr int kRemeshHausdorffSamples = 200000;

struct RemeshReview {
    RemeshResult result;        // its validity is the output's
    ModelComparison comparison; // output row with its resolution (sites) and timings
    ValidityReport inputValidity;
};

struct RemeshReviewOptions {
    // The GUI knows the input's validity from opening it; the CLI's report needs it.
    bool checkInput = true;
};

// `input` needs topology. Progress: the remesh's stages (unnamed), then "Comparing with the input",
// then "Input validity"; Cancelled at any tick.
RemeshReview remeshAndReview(const Model &input, const RemeshParams &params,
                             const RemeshReviewOptions &options = {},
                             Progress &progress = Progress::none());

} // namespace stratamesh
