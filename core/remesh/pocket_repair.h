// Pockets of a remesh (region_shells.h). Near corners where many surfaces meet, the dual mesh can
// give two surfaces that bound one region the same small loop of contact edges, each closing it
// with a fan of triangles around a vertex of its own: the thin space between the two fans is
// cut off from the region (what TetGen's -A floods as an extra region). Re-triangulating one
// fan without its centre and flipping one loop edge out of that surface opens the loop, and
// with it the pocket. Pockets closed otherwise (two surfaces folded onto each other along a
// longer contact) often open by flipping one edge of their triangles.
#pragma once

#include "common/progress.h"
#include "model/model.h"
#include "model/validity.h"

namespace stratamesh {

struct PocketRepair {
    int pockets = 0; // found before the repair
    int opened = 0;  // of them, opened by a kept re-triangulation
};

// Tries, for each pocket and each surface holding some of its triangles: when they are the
// whole fan around one of the surface's own inner vertices, each edge of the fan's loop; then the
// flip of each edge of those triangles. Keeps a change only when the model's validity problems
// decrease. `model` needs topology and keeps it; `validity` is its report, kept
// up to date. Ticks `progress` at each try (each checks validity); throws Cancelled.
PocketRepair repairPockets(Model &model, ValidityReport &validity,
                           Progress &progress = Progress::none());

} // namespace stratamesh
