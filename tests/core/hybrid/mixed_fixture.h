// A small valid mixed mesh built by hand: a right prism (unit right triangle, height 1) with a
// pyramid on each of its three side quads and a tet on its top triangle, so that every boundary
// face is a triangle. The tet is region "cap", the rest region "core"; the prism top is their
// interface. Volumes by hand: core = 1/2 + 1/6 + 1/6 + sqrt(2)/6, cap = 1/6.
#pragma once

#include "mesh/volume_mesh.h"

#include <cmath>

namespace stratamesh::test {

inline VolumeMesh mixedFixture()
{
    VolumeMesh m;
    m.name = "fixture";
    const double s = 0.5 / std::sqrt(2.0);
    m.points = {{0, 0, 0},        {1, 0, 0},
                {0, 1, 0},        {0, 0, 1},
                {1, 0, 1},        {0, 1, 1},
                {0.5, -0.5, 0.5}, {0.5 + s, 0.5 + s, 0.5},
                {-0.5, 0.5, 0.5}, {1.0 / 3, 1.0 / 3, 2}};
    m.cells = {Cell::prism(0, 1, 2, 3, 4, 5), Cell::pyramid(0, 1, 4, 3, 6),
               Cell::pyramid(1, 2, 5, 4, 7), Cell::pyramid(2, 0, 3, 5, 8), Cell::tet(3, 4, 5, 9)};
    m.cellRegion = {0, 0, 0, 0, 1};
    m.regionNames = {"core", "cap"};
    m.surfaces = {{"boundary", "box", FeatureType::Boundary}, {"top", "H1", FeatureType::Horizon}};
    m.triangles = {{0, 2, 1}, {0, 1, 6}, {1, 4, 6}, {4, 3, 6}, {3, 0, 6}, {1, 2, 7},
                   {2, 5, 7}, {5, 4, 7}, {4, 1, 7}, {2, 0, 8}, {0, 3, 8}, {3, 5, 8},
                   {5, 2, 8}, {3, 4, 9}, {4, 5, 9}, {5, 3, 9}, {3, 4, 5}};
    m.triangleSurface.assign(m.triangles.size(), 0);
    m.triangleSurface.back() = 1;
    // One contact segment and one corner: meshio 5.0 cannot read a .vtu with empty line or
    // corner arrays.
    m.edges = {{3, 4}};
    m.edgeLine = {0};
    m.lineNames = {"top_edge"};
    m.corners = {0};
    return m;
}

inline double fixtureCoreVolume()
{
    return 0.5 + 1.0 / 3.0 + std::sqrt(2.0) / 6.0;
}
inline double fixtureCapVolume()
{
    return 1.0 / 6.0;
}

} // namespace stratamesh::test
