// The mesh the remesher builds before it becomes a model (thesis §4.4.4, Algorithm 4.3): output
// points (Algorithm 4.2) shared by all the surfaces they lie on, and triangles tagged with the
// input surface they remesh. Sharing point ids across surfaces is what makes contacts conformal.
#pragma once

#include "model/model.h"

#include <array>
#include <vector>

namespace stratamesh {

// Which case of Algorithm 4.2 produced a point.
enum class PointOrigin { Corner, Line, Surface };

struct OutputPoint {
    Vec3 position = Vec3::Zero();
    PointOrigin origin = PointOrigin::Surface;
    int site = -1;             // Voronoi site whose cell produced it (-1 when unknown)
    std::vector<int> surfaces; // input surfaces it samples (sorted)
    std::vector<int> lines;    // input lines it samples (sorted)
    std::vector<int> corners;  // input corners it samples (sorted)
};

struct OutputTriangle {
    std::array<int, 3> v{-1, -1, -1};
    int surface = -1; // input surface id
};

struct OutputMesh {
    std::vector<OutputPoint> points;
    std::vector<OutputTriangle> triangles;

    // Drops unreferenced points and renumbers; returns old → new point ids (-1 for dropped).
    std::vector<int> compact();
};

// Merges sorted id lists (used when points merge).
void mergeSortedIds(std::vector<int> &into, const std::vector<int> &from);

} // namespace stratamesh
