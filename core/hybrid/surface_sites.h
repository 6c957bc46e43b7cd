// The second stage of the hybrid sampling (thesis §5.2, "Sampling optimization"): after the
// volumetric CVT, the sites sampling the model surfaces (those whose Voronoi cell meets a surface)
// are moved so that their restricted Voronoi diagram on the surfaces is centroidal (§1.3.2),
// Lloyd's way: each such site to the centroid of its restricted cell; the other sites stay.
#pragma once

#include "common/progress.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct SurfaceSitesResult {
    std::vector<Vec3> sites;
    int moved = 0;      // sites with a restricted cell at the last iteration
    int iterations = 0; // Lloyd steps done
};

// `model` has topology. Throws InputError on non-finite sites, Cancelled when cancelled.
SurfaceSitesResult optimizeSurfaceSites(const Model &model, std::vector<Vec3> sites, int iterations,
                                        Progress &progress = Progress::none());

} // namespace stratamesh
