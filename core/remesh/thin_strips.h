// Thin strips: surfaces narrower than the resolution that run between two long lines, such as
// the piece of a fault between the two cutoff lines of one horizon when the throw is small
// (thesis §4.4.3, Fig 4.7, applied to a whole surface instead of one Voronoi cell at a time).
//
// Merging close points cell by cell (Alg 4.2 steps 3–4) decides again in every cell: where a
// cell happens to see only the strip's two lines it keeps the strip, where it sees more it
// merges them, so a long strip comes out in fragments with new corners between them and
// intersecting slivers. Deciding once per strip keeps the result consistent along it: a strip
// narrower than the limit loses its surface and its two lines become one.
#pragma once

#include "model/model.h"

#include <utility>
#include <vector>

namespace stratamesh {

struct ThinStrip {
    int surface = -1;
    std::array<int, 2> lines{-1, -1}; // the two long lines it runs between
    double width = 0.0;  // largest distance from a vertex of the strip to either long line
    double length = 0.0; // length of the shorter long line
};

// (length, line) for the boundary lines of a surface of a model with topology, longest first.
std::vector<std::pair<double, int>> boundaryLinesByLength(const Model &model, int surface);

// Surfaces of `model` (with topology) bounded by two long open lines, whose other boundary lines
// are short ends (each at most twice the limit, and at most a quarter of the long ones), and whose
// every vertex lies within `maxWidth` of both long lines. The box is never a strip.
std::vector<ThinStrip> findThinStrips(const Model &model, double maxWidth);

} // namespace stratamesh
