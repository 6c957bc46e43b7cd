// Flat square models built in code for the unit tests of the remesher's stages (output points,
// dual faces): n×n grids of squares at z = 0 and sites on a regular grid of cell centres.
#pragma once

#include "model/model.h"
#include "model/topology.h"

#include <vector>

namespace stratamesh::test {

// The square [x0, x0 + 1] × [0, 1] at z = 0 meshed by an n×n grid of squares cut in two
// triangles (alternating diagonals), normals up.
inline Surface flatSquare(int n, double x0, const std::string &name)
{
    Surface s;
    s.name = name;
    s.featureName = name;
    s.type = FeatureType::Horizon;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            s.vertices.push_back({x0 + double(i) / n, double(j) / n, 0.0});
    const auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            if ((i + j) % 2 == 0) {
                s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
    return s;
}

// Sites at the centres of a cols×rows grid of cells of side `cell`, shifted by (dx, 0, 0).
inline std::vector<Vec3> gridSites(int cols, int rows, double cell, double dx = 0.0)
{
    std::vector<Vec3> sites;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i)
            sites.push_back({dx + (i + 0.5) * cell, (j + 0.5) * cell, 0.0});
    return sites;
}

// Two unit squares side by side sharing the edge x = 1, with recovered topology: the shared line,
// the two borders, and corners at (1, 0) and (1, 1) where they meet.
inline Model twoSquares(int n)
{
    Model m;
    m.name = "two squares";
    m.surfaces = {flatSquare(n, 0.0, "west"), flatSquare(n, 1.0, "east")};
    return recoverTopology(m);
}

} // namespace stratamesh::test
