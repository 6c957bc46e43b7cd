// The mesh that StrataMesh exports and imports: points, volume cells (tets, pyramids, prisms) with
// regions, boundary/interface triangles with surfaces, and contact-line edges with lines.
// A surface model is the same thing without cells (see model_conversion.h), so every exchange
// format (Gmsh, VTK, TSolid) has one writer and one reader for both.
//
// Node order follows Gmsh and geogram (formats.md §2.5), and a well-oriented cell has a positive
// signedVolume():
//   tet     0 1 2 3        right-handed: (1-0, 2-0, 3-0) has a positive determinant;
//   pyramid 0 1 2 3 | 4    base quad 0-1-2-3, its right-hand normal points towards apex 4;
//   prism   0 1 2 | 3 4 5  node i+3 above node i, the normal of triangle 0-1-2 points towards
//   3-4-5.
// VTK_WEDGE wants the opposite bottom orientation: the VTK writer remaps prisms with [0,2,1,3,5,4].
#pragma once

#include "model/feature_type.h"
#include "model/model.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stratamesh {

enum class CellType : std::uint8_t { Tet, Pyramid, Prism };

constexpr int cellNodeCount(CellType type)
{
    return type == CellType::Tet ? 4 : type == CellType::Pyramid ? 5 : 6;
}
// "tet", "pyramid", "prism".
const char *cellTypeName(CellType type);

struct Cell {
    CellType type = CellType::Tet;
    std::array<int, 6> nodes{-1, -1, -1, -1, -1, -1}; // first cellNodeCount(type) are used

    int size() const { return cellNodeCount(type); }
    static Cell tet(int a, int b, int c, int d) { return {CellType::Tet, {a, b, c, d, -1, -1}}; }
    static Cell pyramid(int a, int b, int c, int d, int apex)
    {
        return {CellType::Pyramid, {a, b, c, d, apex, -1}};
    }
    static Cell prism(int a, int b, int c, int d, int e, int f)
    {
        return {CellType::Prism, {a, b, c, d, e, f}};
    }
    bool operator==(const Cell &o) const { return type == o.type && nodes == o.nodes; }
};

// What a triangle group stands for: a model surface (Gocad TFACE) and its geological feature.
struct MeshSurface {
    std::string name;        // unique in the mesh
    std::string featureName; // geological feature (may be shared by several surfaces)
    FeatureType type = FeatureType::Unknown;
};

struct VolumeMesh {
    std::string name;
    // Points are stored z-up; this remembers a Gocad file's ZPOSITIVE Depth to write it back.
    bool zPositiveDepth = false;
    std::vector<Vec3> points;

    // Volume cells and their regions (index in regionNames, -1 = untagged).
    std::vector<Cell> cells;
    std::vector<int> cellRegion;
    std::vector<std::string> regionNames;
    // Empty, or one list per region: the surfaces bounding it and on which side (RegionSide rule
    // of model.h). Surface models carry their regions only this way.
    std::vector<std::vector<RegionSide>> regionBoundaries;
    // Empty, or one value per cell (e.g. a quality measure), written as cell data where possible.
    std::vector<double> cellQuality;
    std::string qualityName = "quality";

    // Boundary and interface triangles; surface index or -1 = untagged.
    std::vector<Triangle> triangles;
    std::vector<int> triangleSurface;
    std::vector<MeshSurface> surfaces;

    // Contact-line segments; line index or -1 = untagged.
    std::vector<std::array<int, 2>> edges;
    std::vector<int> edgeLine;
    std::vector<std::string> lineNames;

    // Point ids of the model corners (may be empty).
    std::vector<int> corners;

    std::size_t countCells(CellType type) const;
    bool hasCells() const { return !cells.empty(); }
};

// Throws InputError naming the first inconsistency: array sizes, node ids out of range, group ids
// out of range, repeated nodes in a cell, non-finite coordinates. Writers call it first.
void validateMesh(const VolumeMesh &mesh);

// Removes the points no cell, triangle, edge or corner uses, and renumbers the rest in order (a
// surface remesh can leave a vertex whose triangles were all removed; Gmsh warns of such nodes).
void dropUnusedPoints(VolumeMesh &mesh);

// Signed volume of tet abcd: positive when d sees abc counter-clockwise.
double tetVolume(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// Signed volume: positive for a cell in the node order above. Quad faces are bilinear, whose
// volume is the mean of their two diagonal splits (Grandy 1997, "Efficient computation of volume
// of hexahedral cells"): exact for the trilinear cell and independent of the split, so cells
// sharing a warped quad add up to the volume they cover (a fixed split would count the sliver
// between the two splits twice or not at all).
double signedVolume(const VolumeMesh &mesh, const Cell &cell);

// The triangle faces of a cell, each oriented with its right-hand normal pointing out of the cell.
// Tets give 4, pyramids and prisms their triangle faces only (4 and 2).
std::vector<Triangle> outwardTriangleFaces(const Cell &cell);

// Region sides recovered from the cells: a triangle coinciding with a face of a cell of region r
// bounds r, on the positive side when the triangle normal points into the cell. Sorted by surface,
// then negative before positive. Returns one list per region name.
std::vector<std::vector<RegionSide>> regionSidesFromCells(const VolumeMesh &mesh);

} // namespace stratamesh
