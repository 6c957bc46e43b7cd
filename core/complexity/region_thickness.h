// Thickness part C_e of the geometric complexity of regions (thesis §3.3.1, Fig 3.3):
// C_e = A_h / size(B_e), the share of the region's boundary where the region is thinner than h.
//
// How we measure it (the thesis leaves it open): every triangle of every side of the region
// (box sides included: they bound the region too) casts a ray from its centroid along its normal
// turned into the region; the thickness there is the distance to the first surface hit (the
// region is closed, so it is on the region's boundary). A_h is the area of the triangles whose
// thickness is below h; size(B_e) the area of all of them. A wedge between two surfaces meeting
// at an angle θ < 90° is thin over a strip of width about h / tan θ along their contact.
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
std::vector<double> regionThinShares(const Model &model, double h, Progress &progress = Progress::none());

} // namespace stratamesh
