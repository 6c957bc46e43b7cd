// Two surfaces closer than the resolution (a thin lens between a horizon and a fault, thesis
// Fig 4.7b) are sampled by the same cells, whose dual triangles then coincide: the same three
// points in both surfaces. The thesis joins such surfaces; a B-Rep cannot hold one triangle in
// two surfaces, so each copy gets its own vertex on its input surface, on the triangle's normal
// through an interior point (where the surfaces are farthest apart along it), which separates
// them again by the lens thickness.
#pragma once

#include "remesh/editable_soup.h"
#include "remesh/simplification_ledger.h"

namespace stratamesh {

struct DuplicateSeparation {
    int duplicateGroups = 0;  // sets of triangles on the same three points
    int splitTriangles = 0;   // copies split by a vertex on their input surface
    int collapsedSlivers = 0; // duplicated slivers removed by collapsing their shortest edge
    int removedTriangles = 0; // exact copies inside one surface, dropped
    int forced = 0;           // groups whose surfaces meet under the whole triangle: small offsets
    int unseparated = 0;      // groups left as they are (degenerate triangle)
};

// Collapses are ledger records (degenerate_contact_triangle).
DuplicateSeparation separateDuplicateTriangles(EditableSoup &soup, const Model &input,
                                               SimplificationLedger &ledger);

} // namespace stratamesh
