// Statistics of a model's triangulated surfaces, the columns of thesis Table 4.2 (§4.5): sizes,
// smallest angle, share of triangles with an angle below 30°, mean quality Q (Frey & Borouchaki
// 1999), plus total area and the bounding-box diagonal that Hausdorff distances are divided by.
#pragma once

#include "model/model.h"
#include "quality/histogram.h"

#include <cstddef>
#include <vector>

namespace stratamesh {

struct MeshStatistics {
    // Unique vertices: Model::vertices.size() once topology is recovered (exact merge across
    // surfaces), else the sum of the surfaces' own vertices.
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    double minAngleDeg = 0.0;              // 0 when there is no triangle
    double pctTrianglesAngleBelow30 = 0.0; // % of triangles having an angle < 30°
    double meanQuality = 0.0;
    double area = 0.0;
    double bboxDiagonal = 0.0;
};

// Throws InputError when a triangle refers to a vertex the surface does not have.
MeshStatistics computeMeshStatistics(const Model &model);
MeshStatistics computeMeshStatistics(const Surface &surface);

// Fixed default bins: min angle 0–60° by 5°, Q 0–1 by 0.05.
std::vector<double> minAngleBinEdges();
std::vector<double> qualityBinEdges();

// One value per triangle of all surfaces.
Histogram minAngleHistogram(const Model &model,
                            const std::vector<double> &edges = minAngleBinEdges());
Histogram qualityHistogram(const Model &model,
                           const std::vector<double> &edges = qualityBinEdges());

} // namespace stratamesh
