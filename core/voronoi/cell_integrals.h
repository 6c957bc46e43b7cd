// Per-site integrals over the restricted Voronoi cells of a whole model: what the CVT energy
// (thesis eq. 1.6) and the boundary energy (eq. 4.1, integration segments of Fig 4.2) need at
// each optimisation step, without storing the diagram (Lévy & Bonneel 2013 integrate the same
// way). Parallel over triangles with oneTBB; the sums are reduced in a fixed chunk order, so the
// result does not depend on the number of threads.
#pragma once

#include "voronoi/restriction_domain.h"
#include "voronoi/voronoi_neighbours.h"

#include <vector>

namespace stratamesh {

struct CellIntegrals {
    // Surfaces, per site i over V_i ∩ Ω.
    std::vector<double> mass; // ∫ ρ
    std::vector<Vec3> moment; // ∫ ρ (y − s_i); the CVT gradient is −2·moment = 2 m_i (s_i − g_i)
    std::vector<double> energy; // ∫ ρ |y − s_i|²
    std::vector<double> area;   // ∫ 1
    // Lines, per site over V_i ∩ B.
    std::vector<double> length;
    // Boundary energy F_B = Σ over restricted line pieces C1C2 of cell p of ½‖(C1 − p) × (C2 − p)‖²
    // (thesis §4.3.2: ‖N‖ is twice the area of the triangle p C1 C2) and its gradient, including
    // the motion of the piece ends C along their segment when a bisector moves (eq. 4.2–4.3).
    double boundaryEnergy = 0;
    std::vector<Vec3> boundaryGradient;

    double totalEnergy() const;
};

namespace detail {
// One cell's sums over consecutive triangles (or segments) of a chunk, before the reduction.
struct SurfaceRecord {
    int site;
    double area, mass, energy;
    Vec3 moment;
};
struct LineRecord {
    int site;
    double length, energy;
    Vec3 gradient;
};
} // namespace detail

// Reusable state between calls: the owners of the domain points from the previous call serve
// as starting points of the exact owner walks (the result never depends on them), and the
// per-chunk record buffers keep their memory.
struct CellIntegralsWorkspace {
    std::vector<int> pointOwners;
    int siteCount = -1;
    std::vector<std::vector<detail::SurfaceRecord>> surfaceRecords;
    std::vector<std::vector<detail::LineRecord>> lineRecords;
    // The neighbour lists of earlier sites: reused while the sites move little, else where the
    // next k-nearest searches start.
    NeighbourReuse neighbourReuse;
};

struct CellIntegralsOptions {
    bool boundary = true; // compute the line terms (length, F_B)
};

CellIntegrals integrateCells(const RestrictionDomain &domain, const VoronoiNeighbours &delaunay,
                             const CellIntegralsOptions &options,
                             CellIntegralsWorkspace &workspace);

// Exact owner site of every domain point used by a triangle, segment or corner (−1 for
// unused points), walking from the hints in the workspace.
void computePointOwners(const RestrictionDomain &domain, const VoronoiNeighbours &delaunay,
                        CellIntegralsWorkspace &workspace);

} // namespace stratamesh
