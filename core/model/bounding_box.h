// The bounding-box diagonal of a point set: the model's scale, against which tolerances (close
// vertices, TetGen's merge distance) and user distances (d_resolution) are judged.
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh {

// 0 for no point.
double boundingBoxDiagonal(const std::vector<Vec3> &points);
// Over the vertices of every surface: needs no topology.
double boundingBoxDiagonal(const Model &model);

} // namespace stratamesh
