// Point-in-region by the generalised winding number of the region's oriented boundary: the sum
// of the solid angles of its triangles seen from the point, over 4π (Van Oosterom & Strackee
// 1983, "The solid angle of a plane triangle"; Jacobson et al. 2013, "Robust inside-outside
// segmentation using generalized winding numbers"). It needs no ray casting, so it gives a clear
// answer near edges and vertices where a ray would be ambiguous; thesis §5.2 needs one seed
// strictly inside each region of the model.
#pragma once

#include "model/model.h"

namespace stratamesh {

// 1 inside region r, 0 outside, fractional near or on its boundary. A surface listed with both
// signs (a fault ending inside the region) cancels out. Linear in the boundary size.
double regionWindingNumber(const Model &model, int region, const Vec3 &point);

// The region whose winding number at the point is nearest to 1 (and above 0.5), or -1.
int locateRegion(const Model &model, const Vec3 &point);

} // namespace stratamesh
