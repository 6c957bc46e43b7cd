// Objective of the site optimisation (thesis §1.3.2 and §4.3.2):
//   F = (1 − α)·F_CVT + α·F_B
// with F_CVT = Σ_i ∫_{V_i∩Ω} ρ(y)‖y − s_i‖² dy (eq. 1.6, ρ linear on each input triangle) and
// F_B the boundary energy of eq. 4.1 evaluated on the integration segments of Fig 4.2 (see
// CellIntegrals::boundaryEnergy). ∇F_CVT_i = 2·m_i·(s_i − g_i) (Du et al. 1999; Liu et al. 2009).
#pragma once

#include "voronoi/cell_integrals.h"
#include "voronoi/restriction_domain.h"

#include <vector>

namespace stratamesh {

struct CvtEvaluation {
    double energy = 0;          // F
    double cvtEnergy = 0;       // F_CVT
    double boundaryEnergy = 0;  // F_B
    std::vector<Vec3> gradient; // ∇F, one per site
    CellIntegrals cells;
    double delaunaySeconds = 0; // neighbours of the sites (Delaunay or kd-tree)
    double rvdSeconds = 0;

    double gradientNorm() const;
};

// Evaluates F and ∇F at the sites. workspace carries the owner hints between calls.
CvtEvaluation evaluateCvtEnergy(const RestrictionDomain &domain, const std::vector<Vec3> &sites,
                                double alpha, CellIntegralsWorkspace &workspace,
                                NeighbourSearch search = NeighbourSearch::NearestNeighbours);

} // namespace stratamesh
