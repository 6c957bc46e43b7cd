// The B-Rep structural model (thesis §3.2): corners, lines, surfaces and regions.
#pragma once

#include "model/feature_type.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace stratamesh {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

// A triangulated patch (Gocad TFACE). Vertex ids are local to the surface: connectivity inside a
// surface comes from these ids only, never from positions (files cut surfaces with duplicates).
struct Surface {
    std::string name;        // unique in the model, e.g. "h1_model1_2"
    std::string featureName; // geological feature (GEOLOGICAL_FEATURE, or the TSURF name)
    FeatureType type = FeatureType::Unknown;
    std::string sourceObject; // name of the object in the file it came from (TSURF name)
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;

    // Filled by topology recovery.
    std::vector<int> lines;   // boundary lines (each listed once, even when internal)
    std::vector<int> regions; // incident regions (not the Universe)
};

// A contact or border polyline. Vertex ids index Model::vertices.
struct Line {
    std::string name;
    std::vector<int> vertices; // ordered; for a closed line the first is not repeated
    bool closed = false;
    std::array<int, 2> corners{-1, -1}; // end corners; -1 for a closed line
    std::vector<int> surfaces;          // incident surfaces, sorted
};

struct Corner {
    int vertex = -1;        // index in Model::vertices
    std::vector<int> lines; // incident lines, sorted
};

// One boundary surface of a region with its side: positive means the region lies on the side the
// surface normal points to (Gocad "+k", formats.md §0), in the z-up frame.
struct RegionSide {
    int surface = -1;
    bool positive = true;
    bool operator==(const RegionSide &o) const
    {
        return surface == o.surface && positive == o.positive;
    }
};

struct Region {
    std::string name;
    std::vector<RegionSide> boundaries;
};

struct Layer {
    std::string name;
    std::vector<int> regions;
};

struct Model {
    std::string name;
    // Coordinates are always stored z-up; this remembers the file's convention to write it back.
    bool zPositiveDepth = false;

    std::vector<Surface> surfaces;
    std::vector<Region> regions;      // the Universe is not a region
    std::vector<RegionSide> universe; // its sides as read (empty when the file had none)
    std::vector<Layer> layers;

    // Derived by recoverTopology(): unique points (surface vertices merged by exact position
    // across surfaces), the map from each surface's local vertices to them, lines and corners.
    std::vector<Vec3> vertices;
    std::vector<std::vector<int>> surfaceVertexToGlobal;
    std::vector<Line> lines;
    std::vector<Corner> corners;

    std::size_t triangleCount() const;
    bool hasTopology() const
    {
        return surfaceVertexToGlobal.size() == surfaces.size() && !surfaces.empty();
    }
};

} // namespace stratamesh
