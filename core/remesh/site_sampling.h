// Sites for the remesher: initial random sampling of the model surfaces proportional to area ×
// density (thesis Algorithm 4.1 step 1, after Lévy & Bonneel 2013), and Lloyd relaxation over the
// restricted Voronoi diagram (thesis §1.3.3; Lloyd 1982). The remesher uses the engine's L-BFGS
// CVT with the boundary energy (core/cvt, thesis §4.3) when available; Lloyd is the fallback.
#pragma once

#include "common/progress.h"
#include "voronoi/restriction_domain.h"

#include <vector>

namespace stratamesh {

// n points on the domain triangles, seeded: the same seed gives the same sites.
std::vector<Vec3> sampleSites(const RestrictionDomain &domain, int n, unsigned seed);

struct LloydResult {
    std::vector<Vec3> sites;
    std::vector<double> energy; // CVT energy F before each step, then after the last
};

// Moves every site to the (density-weighted) centroid of its restricted cell, `iterations` times.
LloydResult lloydRelaxation(const RestrictionDomain &domain, std::vector<Vec3> sites, int iterations,
                            Progress &progress = Progress::none());

} // namespace stratamesh
