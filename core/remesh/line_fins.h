// Fins along contact lines. Where several surfaces meet at a line at small angles (a horizon
// crossing a dipping fault with no throw: four sheets around one line), a Voronoi edge can pierce
// a surface so close to the line that the three cells around it all have their point on the line:
// the dual triangle then joins three consecutive points of the line, a fin lying along it, and the
// surface's other triangle on the fin's long edge skips the middle point, which the surfaces across
// the line do use. The same fin often comes out of two surfaces, as a duplicate triangle.
// The fin is dropped and the long edge split at the middle point in that surface (thesis Alg 4.4,
// configuration 6, Fig 4.9d, applied to a vertex that is already on the contact).
#pragma once

#include "remesh/editable_soup.h"

namespace stratamesh {

// Returns the number of fins removed.
int removeLineFins(EditableSoup &soup);

} // namespace stratamesh
