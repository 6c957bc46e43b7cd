// The benchmark cases of the Voronoi engine (issue 3): a real model and a large generated
// surface, each optimised with the default CVT parameters.
#pragma once

#include "voronoi/restriction_domain.h"
#include "voronoi/voronoi_neighbours.h"

#include <string>
#include <vector>

namespace stratamesh::bench {

struct BenchResult {
    std::string name;
    std::size_t triangles = 0;
    std::size_t segments = 0;
    int sites = 0;
    int iterations = 0;
    int evaluations = 0;
    double setupSeconds = 0;    // reading, topology, domain, sampling
    double totalSeconds = 0;    // optimisation
    double rvdSeconds = 0;      // restricted Voronoi integration, all evaluations
    double delaunaySeconds = 0; // neighbours of the sites, all evaluations
    int neighbourSearches = 0;  // k-nearest searches; the other evaluations reused the lists
    double finalRvdSeconds = 0; // one full symbolic diagram at the end (components included)
    double peakRssMb = 0;
    int threads = 0;
    double firstEnergy = 0, lastEnergy = 0;
};

// A smooth height field over [0, 1]² with about `triangles` triangles, as one surface.
RestrictionDomain generatedSurface(int triangles);

BenchResult runCase(const std::string &name, const RestrictionDomain &domain, int sites,
                    int iterations, double alpha, int threads, NeighbourSearch search,
                    double setupSeconds);

double peakRssMb();

// "  <what> over N runs: min …, median …, max … s", for timings of repeated runs in one process
// (the machine's load varies between runs; the spread shows by how much). Nothing for one run.
void printSpread(const char *what, std::vector<double> seconds);

} // namespace stratamesh::bench
