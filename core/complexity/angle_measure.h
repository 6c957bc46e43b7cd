// Angle part C_a of the geometric complexity (thesis §3.3.1, Fig 3.3), relative to an angle α.
//
// How we measure it (the thesis leaves it open):
// - region: along every line edge of the region's boundary (box lines included), the region
//   fills one or more wedges between the half-planes of its boundary triangles around the edge;
//   the edge is sharp when its narrowest wedge is below α. C_a = length of sharp line edges /
//   length of all line edges on the region's boundary (0 when it has none).
// - surface: at every corner of the surface's lines, each local vertex of the surface there (a
//   cut surface has several) has the sum of its triangle angles as the surface's angle; it is
//   sharp below α. C_a = sharp corner vertices / corner vertices (0 when there is none).
// - lines: 0 (the thesis defines C_a for regions and surfaces only).
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh {

// C_a of each region (order of Model::regions). Requires topology.
std::vector<double> regionSharpShares(const Model &model, double alphaDegrees);
// C_a of one surface. Requires topology.
double surfaceSharpCornerShare(const Model &model, int surface, double alphaDegrees);

// The angle inside a region at a line edge, between the half-plane of triangle 0 (inward normal
// m0: the region is on that side) and the nearest other half-plane met by turning towards m0.
// v_i: unit vectors in each half-plane, perpendicular to the edge, pointing away from it.
// Returns 2π when there is no other half-plane. Exposed for tests.
double wedgeAngle(const Vec3 &v0, const Vec3 &m0, const std::vector<Vec3> &others);

} // namespace stratamesh
