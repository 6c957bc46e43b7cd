// Thickness part C_e of the geometric complexity of regions (thesis §3.3.1, Fig 3.3):
// C_e = A_h / size(B_e), the share of the region's boundary where the region is thinner than h.
//
// How we measure it (the thesis leaves it open): the thickness of the region at a point p of its
// boundary is the distance from p to the rest of its boundary, i.e. to the nearest of its other
// boundary surfaces (box sides included: they bound the region too). Each triangle of each side
// counts by its area, thin when its centroid is closer than h to another boundary surface of the
// region. So a layer thinner than h is thin all over its horizons, and every region is thin in a
// strip of width about h along its contact lines (wider where the surfaces meet at an acute
// angle). This reading reproduces the thesis's Table 3.2 region column (sums over the regions of
// C_t + C_f + C_e + C_a, h = 100 m: A1 0.12 vs 0.13, A2 0.65 vs 0.59, A5 1.19 vs 1.19), where a
// thickness measured across the region along the inward normal gives 0.00, 0.05 and 0.14.
#pragma once

#include "common/progress.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

// Boundary area of a region on one of its sides, and the part of it where the region is thin.
struct SideThinArea {
    RegionSide side;
    double thin = 0.0;
    double all = 0.0;
};

// Per region (order of Model::regions), per side (order of Region::boundaries).
std::vector<std::vector<SideThinArea>> regionSideThinAreas(const Model &model, double h,
                                                           Progress &progress = Progress::none());

// C_e of each region, in the order of Model::regions.
std::vector<double> regionThinShares(const Model &model, double h,
                                     Progress &progress = Progress::none());

} // namespace stratamesh
