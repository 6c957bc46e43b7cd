// A sizing field from the local feature size of a B-Rep, feeding the CVT density (thesis §4.6.2:
// "adapting site density to a distance to the corners and other model elements"; Amenta & Bern
// 1999 ε-sampling, Cheng, Dey & Ramos 2007 for piecewise smooth complexes). Where a restricted
// Voronoi cell is larger than the distance between two features that do not meet, it holds both
// and the remesh merges them or strings needles between them; cells as small as that distance
// keep each feature in cells of its own.
//
// The local feature size at a model vertex is its distance to the nearest feature (corner, line
// segment, or for line vertices and corners a surface triangle) that is not incident to the
// vertex's own feature: for a corner, other corners, lines not ending at it and surfaces not
// holding it; for a line vertex, corners not ending the line, other lines and surfaces not
// bounded by it; for a vertex inside a surface, corners and lines not on its boundary (close
// surfaces are kept apart by the cell components, thesis Fig 4.4, and need no finer cells).
// Two features sharing a corner c count only where they are closer than α·|p − c|: lines meeting
// at a corner at an angle above asin(α) do not refine it, sharper wedges are refined towards it.
// The size h = clamp(κ·lfs, h_min, h0) is then graded (h(p) ≤ h(q) + g·|p − q|) so that cells grow
// smoothly away from the features.
#pragma once

#include "common/progress.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct FeatureSizingParams {
    double edgeLength = 0.0;    // h0: the size away from features
    double lfsFactor = 1.0;     // κ: h = κ · lfs near features
    double gradation = 0.4;     // g: the largest growth of h per unit length
    double minEdgeLength = 0.0; // h_min: features closer than h_min / κ are not refined further
    double wedgeSine = 0.26; // α (sin 15°): features sharing a corner c count below α·|p − c|
    // Features closer than this are left to be merged (Alg 4.2 step 4) rather than refined:
    // cells small enough to part them would keep them apart. 0 refines every feature.
    double dResolution = 0.0;
};

struct FeatureSizing {
    std::vector<double> lfs;  // per model vertex; +inf where no feature is within reach (h0 / κ)
    std::vector<double> size; // h per model vertex, graded, in [h_min, h0]
    // (1/A) ∫ (h0 / h)² dA over the surfaces: the sites this field needs over those of a uniform
    // h0 (≥ 1).
    double siteFactor = 1.0;
    int refinedVertices = 0;  // vertices where h < h0
    double smallestLfs = 0.0; // over the vertices where it is finite; +inf when none
};

// `model` with topology. Throws InputError on a non-positive edge length.
FeatureSizing computeFeatureSizing(const Model &model, const FeatureSizingParams &params,
                                   Progress &progress = Progress::none());

// The two halves: the local feature size of every vertex of `model` (with topology), searched
// within `reach` (+inf beyond); then the graded size field from it (its `lfs` is `lfs`).
std::vector<double> localFeatureSizes(const Model &model, double reach, double wedgeSine,
                                      Progress &progress = Progress::none());
FeatureSizing sizingFromLfs(const Model &model, std::vector<double> lfs,
                            const FeatureSizingParams &params);

// The CVT density of the field, per model vertex: ρ = (h0 / h)⁴, since a 2D centroidal Voronoi
// tessellation spaces its sites as ρ^(-1/4) (Du, Faber & Gunzburger 1999).
std::vector<double> sizingDensity(const FeatureSizing &sizing, double edgeLength);

} // namespace stratamesh
