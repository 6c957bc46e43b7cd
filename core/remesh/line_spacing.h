// Line vertices as far apart as the surfaces beside them. The dual of the restricted Voronoi
// diagram puts a point on a contact for every cell that crosses it, from the surfaces on both
// sides, so lines come out about twice as dense as the surfaces; a surface narrower than two
// cells between two lines (a fault piece between two horizons) then gets no vertex of its own
// and is a strip of needles from one line to the other (network5 at 5000 sites: 16 % of the
// triangles have three vertices on lines, 24 % of those are under 30°).
#pragma once

#include "remesh/editable_soup.h"

namespace stratamesh {

struct LineSpacingParams {
    // A line vertex goes when its two line edges together are shorter than this times the mean
    // of its other edges (those into the surfaces).
    double ratio = 1.2;
    int passes = 3;
};

// Collapses such line vertices onto their nearer line neighbour, when fewer triangles around are
// under 30° after than before and none is worse than the worst one there before; lines, corners
// and surfaces are kept, and no collapse adds a crossing of two triangles. Returns the number of
// vertices removed.
int spaceLineVertices(EditableSoup &soup, const LineSpacingParams &params = {});

} // namespace stratamesh
