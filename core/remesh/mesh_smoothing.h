// Vertex relaxation of the output mesh after the thesis's post-processing (§4.4.5): interior
// vertices move towards the centroid of their neighbours, or a quarter of the way to one of them,
// and back onto their input surface; line vertices towards the middle of their two line
// neighbours, or part of the way to one, and back onto their input line; the candidate with the
// best worst quality around the vertex wins; corners never move. A move is kept only when no
// triangle flips and the worst quality around the vertex does not decrease, so it never damages
// the mesh the dual construction gave; moved vertices of triangles that end up crossing another
// surface go back where they were.
#pragma once

#include "common/progress.h"

#include "remesh/editable_soup.h"
#include "remesh/input_projector.h"

namespace stratamesh {

struct SmoothingParams {
    int passes = 3;
    bool lines = true; // also relax line vertices along their input lines
};

// Number of vertex moves kept.
int relaxVertices(EditableSoup &soup, InputProjector &projector, const SmoothingParams &params = {},
                  Progress &progress = Progress::none());

} // namespace stratamesh
