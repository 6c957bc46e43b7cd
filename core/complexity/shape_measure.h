// Shape measure C_f of the geometric complexity (thesis §3.3.1, Fig 3.3): 1 − size of the
// projection of an element onto its mean line or plane ÷ its size; 0 for regions.
//
// How we measure it (the thesis leaves it open):
// - surface: the mean plane is the one whose normal is the area-weighted mean normal
//   A = Σ_t area_t n_t (it maximises the signed projected area); the projection size is |A|,
//   the area of the projection counted with its winding number, so a fold that turns back over
//   itself is not counted twice. C_f = 1 − |A| / area: 0 for a plane, ~1 − cos θ for a surface
//   tilted by ±θ around its mean plane, 1 for a closed surface.
// - line: the mean line is the least-squares line of the polyline (principal axis of its
//   length-weighted covariance); the projection is the interval spanned by the vertices on it.
//   C_f = 1 − interval length / line length: 0 for a straight line.
#pragma once

#include "model/model.h"

namespace stratamesh {

double surfaceShapeMeasure(const Surface &surface);
double lineShapeMeasure(const Model &model, const Line &line);

} // namespace stratamesh
