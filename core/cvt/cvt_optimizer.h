// Optimisation of the sites over a whole model (thesis Alg. 4.1, §1.3.3, §4.3): minimises
// F = (1 − α)·F_CVT + α·F_B with L-BFGS (Nocedal 1980; Liu et al. 2009, "On centroidal
// Voronoi tessellation — energy smoothness and fast computation"; LBFGSpp), or runs Lloyd
// iterations (sites to the centroids of their restricted cells, F_CVT only).
#pragma once

#include "common/progress.h"
#include "voronoi/restriction_domain.h"
#include "voronoi/voronoi_neighbours.h"

#include <functional>
#include <string>
#include <vector>

namespace stratamesh {

struct CvtIterationReport {
    int iteration = 0;       // 1-based
    double energy = 0;       // F after the iteration
    double gradientNorm = 0; // ‖∇F‖ after the iteration
};

struct CvtParams {
    int iterations = 100;         // at most this many iterations
    double gradientTolerance = 0; // stop once ‖∇F‖ ≤ this (0: never)
    double alpha = 0;             // weight of the boundary energy, in [0, 1]
    bool lloyd = false;           // Lloyd iterations instead of L-BFGS (requires alpha = 0)
    int threads = 0;              // 0: oneTBB's default (all cores)
    int lbfgsMemory = 7;          // number of correction pairs kept by L-BFGS
    // Neighbours of the sites at each evaluation: k nearest sites (default), or the Delaunay
    // triangulation; the diagram is the same, the k nearest are found 4 times faster on
    // modelA5 at 5000 sites (voronoi_neighbours.h).
    NeighbourSearch neighbourSearch = NeighbourSearch::NearestNeighbours;
    // Sites that keep their place (non-zero entries, same indices as the sites; empty: none):
    // their gradient is taken as zero, so L-BFGS and Lloyd leave them where they are.
    std::vector<char> fixedSites;
    // Called after each iteration (from the calling thread); Progress::tick follows it, so a
    // cancel requested there stops the run with Cancelled.
    std::function<void(const CvtIterationReport &)> onIteration;
};

struct CvtResult {
    std::vector<Vec3> sites;
    double initialEnergy = 0;
    double initialGradientNorm = 0;
    std::vector<double> energy;       // per iteration
    std::vector<double> gradientNorm; // per iteration
    int iterations = 0;
    int evaluations = 0;    // energy evaluations (line searches may need several)
    int relocatedSites = 0; // sites put back after their cell became empty
    std::string stopReason; // "iterations", "gradient", "line search", "no descent"
    double totalSeconds = 0;
    double rvdSeconds = 0;      // restricted Voronoi integration, summed
    double delaunaySeconds = 0; // neighbours of the sites (Delaunay or kd-tree), summed
    int neighbourSearches = 0;  // k-nearest lists searched afresh
    int threads = 0;
};

// Throws InputError on bad parameters or no sites, Cancelled when progress is cancelled.
CvtResult optimizeCvt(const RestrictionDomain &domain, const std::vector<Vec3> &initialSites,
                      const CvtParams &params, Progress &progress = Progress::none());

} // namespace stratamesh
