// Removal of thin strips from a model before remeshing (thin_strips.h says why per strip, not
// per Voronoi cell): the strip's surface is deleted and its two long lines become one line
// half-way between them, or on one of them when half-way does not go cleanly and the strip is at
// most half the width limit (no line moves farther than half-way merging may), so the surfaces on
// both sides meet there; its short end lines shrink to a point. Merging the two lines needs no
// tolerance: both are parametrised along the first one, their vertices are merged in one order, and
// every edge of either line is split at the other line's vertices, so the surfaces on both sides
// share one polyline exactly.
//
// The surfaces next to a strip only stretch: the strip lies between them (the gap between the two
// cutoff lines of a horizon on a fault, or a thin piece of a fault between two others), so moving
// its lines towards each other moves their borders away from their interiors.
#pragma once

#include "common/progress.h"
#include "remesh/simplification_ledger.h"
#include "remesh/thin_strips.h"

namespace stratamesh {

struct StripCollapse {
    Model model;                     // with topology; `input` itself when nothing was removed
    std::vector<ThinStrip> removed;  // ids refer to the input model
    std::vector<int> surfaceToInput; // model surface → input surface
};

// Removes the thin strips of `input` (with topology) narrower than `maxWidth`, one at a time
// (removing one can make a neighbour a strip of merged lines), and records each in the ledger:
// a close_feature_merge of its two lines and a surface_lost. A strip whose removal would join a
// surface to itself, or whose merged line would fold a triangle or add any problem to the validity
// report wherever it may be put (half-way; on either line when at most maxWidth / 2 wide), is
// kept.
// Throws Cancelled when cancelled (checked between strips).
StripCollapse removeThinStrips(const Model &input, double maxWidth, SimplificationLedger &ledger,
                               Progress &progress = Progress::none());

} // namespace stratamesh
