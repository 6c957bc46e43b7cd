// Gmsh element type codes of the first-order elements we exchange (formats.md §2.3).
#pragma once

#include "mesh/volume_mesh.h"

namespace stratamesh {

constexpr int gmshLine = 1;
constexpr int gmshTriangle = 2;
constexpr int gmshQuadrangle = 3;
constexpr int gmshTet = 4;
constexpr int gmshHexahedron = 5;
constexpr int gmshPrism = 6;
constexpr int gmshPyramid = 7;
constexpr int gmshPoint = 15;

inline int gmshTypeOf(CellType type)
{
    return type == CellType::Tet ? gmshTet : type == CellType::Pyramid ? gmshPyramid : gmshPrism;
}

// Node count of a supported type, 0 for any other.
inline int gmshNodeCount(int type)
{
    switch (type) {
    case gmshPoint:
        return 1;
    case gmshLine:
        return 2;
    case gmshTriangle:
        return 3;
    case gmshTet:
        return 4;
    case gmshPyramid:
        return 5;
    case gmshPrism:
        return 6;
    default:
        return 0;
    }
}

inline const char *gmshTypeName(int type)
{
    switch (type) {
    case gmshPoint:
        return "point";
    case gmshLine:
        return "line";
    case gmshTriangle:
        return "triangle";
    case gmshQuadrangle:
        return "quadrangle";
    case gmshTet:
        return "tetrahedron";
    case gmshHexahedron:
        return "hexahedron";
    case gmshPrism:
        return "prism";
    case gmshPyramid:
        return "pyramid";
    default:
        return "higher-order or unknown element";
    }
}

} // namespace stratamesh
