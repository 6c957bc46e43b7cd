// Volumetric centroidal Voronoi tessellation of an axis-aligned box: the neighbourhoods of the
// local complexity measures (thesis §3.5.2 "Method"; CVT §1.3.1). Lloyd's algorithm: move each
// site to the centroid of its cell clipped to the box. The CVT energy F = Σ_i ∫_{V_i} |x − s_i|²
// never increases under a Lloyd step (Du, Faber, Gunzburger 1999, "Centroidal Voronoi
// tessellations: applications and algorithms", SIAM Review 41(4)).
#pragma once

#include "common/progress.h"
#include "complexity/convex_polyhedron.h"

#include <cstdint>
#include <vector>

namespace stratamesh {

struct BoxCvtParams {
    int sites = 1000;
    int iterations = 30;    // Lloyd steps at most
    std::uint64_t seed = 1; // initial sites: uniform in the box from a mt19937_64 stream
    // Stop early when no site moves more than this fraction of the mean cell size.
    double tolerance = 1e-4;
};

struct BoxCvt {
    Box3 box;
    std::vector<Vec3> sites;
    std::vector<ConvexPolyhedron> cells; // cells[i] belongs to sites[i]
    std::vector<double> energy;          // F before each step; the last entry is F of sites
    int iterations = 0;                  // Lloyd steps done
};

// Uniform random sites in the box; the same seed gives the same sites on every platform.
std::vector<Vec3> randomSitesInBox(const Box3 &box, int count, std::uint64_t seed);

double cvtEnergy(const std::vector<Vec3> &sites, const std::vector<ConvexPolyhedron> &cells);

// Throws InputError when sites < 1 or the box has no volume.
BoxCvt runBoxCvt(const Box3 &box, const BoxCvtParams &params,
                 Progress &progress = Progress::none());

} // namespace stratamesh
