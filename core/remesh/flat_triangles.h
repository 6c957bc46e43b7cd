// Flat triangles left in a finished remesh. The dual mesh's cleanup (mesh_cleanup.h, line_fins.h)
// mends the caps it sees, but only where the apex may move (an inner vertex) or shares one line
// with the long edge; an apex on a corner between two lines is left, and pocket opening
// (pocket_repair.h) re-triangulates after the cleanup. A 10-fault network remeshed at 5000 sites
// kept a triangle of F6_4 with angles 0°, 180°, 0° along its contact with H1_b5 and H2_b6.
// Such a triangle is dropped and its long edge split at its apex in every surface holding that
// edge, the same operation as thesis Alg 4.4, configuration 6, on a vertex that is already there.
#pragma once

#include "common/progress.h"
#include "model/model.h"
#include "model/validity.h"

namespace stratamesh {

struct FlatTriangleRepair {
    int found = 0;  // flat triangles tried (each once)
    int mended = 0; // of them, replaced by a kept split
};

// Tries the triangles whose widest angle is at least `apexDeg`, flattest first, at most
// `maxTries` of them. A split is kept only when the worst smallest angle of the triangles it
// makes beats that of the triangles it replaces, no new triangle meets another surface, and
// no validity check finds more problems than before. `model` needs topology and keeps it;
// `validity` is its report, kept up to date. Throws Cancelled.
FlatTriangleRepair mendFlatTriangles(Model &model, ValidityReport &validity, double apexDeg = 170.0,
                                     int maxTries = 16, Progress &progress = Progress::none());

} // namespace stratamesh
