// Topology recovery of a B-Rep model from its conformal surfaces (thesis §3.2, Fig 3.1):
// unique points, contact lines and corners, and the surface ↔ line ↔ corner ↔ region incidences.
// Pellerin et al. 2015, "Elements for measuring the complexity of 3D structural models".
//
// Definitions (they do not depend on any particular model):
// - Global vertices: surface vertices merged by EXACT position across surfaces. Inside one surface,
//   connectivity comes from local vertex ids only (files cut surfaces along internal lines with
//   duplicated vertices), so two local vertices at one position share a global id but never an
//   edge.
// - An edge is a pair of global vertices; its incident surfaces are the surfaces having it as an
//   edge. It is a line edge when it is on the border of some surface (one triangle around a local
//   edge) or when it belongs to two or more surfaces.
// - A corner is a vertex with a number of line edges other than two, or whose two line edges have
//   different incident surface sets. Lines are maximal chains of line edges between corners; a
//   cycle of line edges without any corner is a closed line (no corner).
#pragma once

#include "model/model.h"

namespace stratamesh {

// Returns the model with vertices, surfaceVertexToGlobal, lines, corners, Surface::lines and
// Surface::regions filled (any previous topology is replaced). Linear in the model size (hashing).
// Throws InputError on a non-finite coordinate or a triangle index out of range.
//
// A line that starts and ends at the same corner is open (closed == false) with corners {c, c};
// its vertex list then starts and ends with the corner's vertex.
Model recoverTopology(Model model);

} // namespace stratamesh
