// Exact side predicates of the restricted Voronoi diagram on symbolic points (thesis §1.2.2;
// Lévy & Bonneel 2013, "Variational anisotropic surface meshing with Voronoi parallel linear
// enumeration", §3: predicates on symbolic vertices; Edelsbrunner & Mücke 1990 for the
// symbolic perturbation).
//
// Every RVD vertex is one of
//   - an input vertex q,
//   - an input edge (q0, q1) ∩ bisector(i, j),
//   - an input triangle (q0, q1, q2) ∩ bisector(i, j) ∩ bisector(i, k) (a Voronoi edge),
// and clipping the cell of site i by the bisector of (i, l) asks on which side of it such a
// point lies. These functions answer from the input coordinates, never from a computed position:
// a floating-point evaluation with a rigorous error bound, then exact arithmetic when in doubt.
//
// Ties are broken by a symbolic perturbation: the power distance to site a is
// |x − p_a|² − w_a with infinitesimal weights w_0 ≫ w_1 ≫ … (lower index wins a tie). The
// perturbed diagram is a power diagram, so its cells stay convex and every decision is
// consistent with every other: the same symbolic point gets the same answer in all cells.
#pragma once

#include "model/model.h"

namespace stratamesh::rvd {

// +1 when q is strictly closer to site i than to site l (after perturbation), −1 otherwise.
int sideOfInputVertex(const Vec3 &q, const Vec3 &pi, int i, const Vec3 &pl, int l);

// Same question for x = segment (q0, q1) ∩ bisector(i, j). The segment must cross the bisector.
int sideOfEdgeVertex(const Vec3 &q0, const Vec3 &q1, const Vec3 &pi, int i, const Vec3 &pj, int j,
                     const Vec3 &pl, int l);

// Same question for x = plane(q0, q1, q2) ∩ bisector(i, j) ∩ bisector(i, k).
int sideOfFaceVertex(const Vec3 &q0, const Vec3 &q1, const Vec3 &q2, const Vec3 &pi, int i,
                     const Vec3 &pj, int j, const Vec3 &pk, int k, const Vec3 &pl, int l);

// How many evaluations needed exact arithmetic since the process started (diagnostics).
long long exactPredicateCount();

} // namespace stratamesh::rvd
