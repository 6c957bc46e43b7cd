// Hausdorff distance between two triangulated models (thesis §4.5, Table 4.2, which used Metro /
// MESH by Aspert, Santa-Cruz & Ebrahimi 2002, "MESH: measuring errors between surfaces using the
// Hausdorff distance", ICME). Both sides are sampled densely (every vertex, every triangle on a
// barycentric grid whose density follows its area); each sample's distance to the other side is
// the exact point-to-triangle distance found with a CGAL AABB tree, so only the sampled side is
// approximated. The result is given in model units and in % of the bounding-box diagonal.
#pragma once

#include "common/progress.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct HausdorffParams {
    int samplesPerSide =
        200000; // grid samples spread over each side by area (vertices come on top)
};

struct HausdorffResult {
    double aToB = 0.0; // max over samples of A of the distance to B
    double bToA = 0.0;
    double symmetric = 0.0; // max(aToB, bToA)
    double meanAToB = 0.0;
    double meanBToA = 0.0;
    double bboxDiagonal = 0.0; // of A (the input model in a remeshing comparison)
    double symmetricPctBbox = 0.0;
    // Distance from each vertex of B (surface by surface, local vertex ids) to A: for colouring
    // the output model by its distance to the input.
    std::vector<std::vector<double>> vertexDistanceBToA;
};

// A and B need no topology. Throws InputError when either has no triangle.
HausdorffResult hausdorffDistance(const Model &a, const Model &b,
                                  const HausdorffParams &params = {},
                                  Progress &progress = Progress::none());

// Distance from each point to the nearest triangle of the model (exact, AABB tree).
std::vector<double> distancesToModel(const Model &model, const std::vector<Vec3> &points);

} // namespace stratamesh
