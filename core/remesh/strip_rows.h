// A row of vertices down the middle of strips of tall triangles. A surface piece about one cell
// wide between two lines (a fault piece between two horizons) gets no vertex of its own from the
// dual construction, and its lines carry points from the cells on both sides, about twice as
// dense as the surface: every triangle then stands on a short line edge with its apex on the
// other line, about twice as tall as wide (apex angle near 28°). No flip or slide mends that;
// a vertex in the middle of each rung (an edge from one line to the other) halves the height,
// and relaxation and flips then space the row (3-fault network at 5000 sites: most of the
// triangles under 30° that stand on a line edge).
#pragma once

#include "common/progress.h"
#include "remesh/editable_soup.h"
#include "remesh/input_projector.h"

namespace stratamesh {

struct StripRowParams {
    double minAngleDeg = 30.0; // triangles whose apex angle on a line edge is below this
    int relaxPasses = 3;
};

// Splits the rungs of the strip triangles under the angle at the middle, on the input surface,
// then relaxes and flips; keeps the result only when it has fewer triangles under the angle and
// no more crossings of two triangles. Returns the number of vertices added.
int addStripRows(EditableSoup &soup, InputProjector &projector, const StripRowParams &params = {},
                 Progress &progress = Progress::none());

} // namespace stratamesh
