#include "hybrid/cell_quality.h"

#include "hybrid/cell_faces.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace stratamesh {

namespace {

constexpr double pi = 3.14159265358979323846;

Vec3 faceNormal(const VolumeMesh &m, const CellFace &f)
{
    const auto &p = m.points;
    const auto &n = f.nodes;
    if (f.isQuad())
        return (p[n[2]] - p[n[0]]).cross(p[n[3]] - p[n[1]]).normalized();
    return (p[n[1]] - p[n[0]]).cross(p[n[2]] - p[n[0]]).normalized();
}

} // namespace

DihedralRange cellDihedrals(const VolumeMesh &mesh, const Cell &cell)
{
    const std::vector<CellFace> faces = outwardFaces(cell);
    std::map<std::pair<int, int>, std::vector<Vec3>> edgeNormals;
    for (const CellFace &f : faces) {
        const Vec3 n = faceNormal(mesh, f);
        for (int k = 0; k < f.size; ++k) {
            const int a = f.nodes[k], b = f.nodes[(k + 1) % f.size];
            edgeNormals[{std::min(a, b), std::max(a, b)}].push_back(n);
        }
    }
    DihedralRange r;
    for (const auto &[edge, normals] : edgeNormals) {
        if (normals.size() != 2)
            continue;
        const double between =
            std::acos(std::clamp(normals[0].dot(normals[1]), -1.0, 1.0)) * 180.0 / pi;
        const double dihedral = 180.0 - between;
        r.minDegrees = std::min(r.minDegrees, dihedral);
        r.maxDegrees = std::max(r.maxDegrees, dihedral);
    }
    return r;
}

namespace {

void addCell(TypeQuality &t, CellType type, const DihedralRange &r)
{
    ++t.cells;
    t.meanMinDihedral += (r.minDegrees - t.meanMinDihedral) / static_cast<double>(t.cells);
    t.minDihedral = std::min(t.minDihedral, r.minDegrees);
    t.maxDihedral = std::max(t.maxDihedral, r.maxDegrees);
    if (type == CellType::Tet && (r.minDegrees < 5.0 || r.maxDegrees > 175.0))
        ++t.slivers;
}

} // namespace

std::array<TypeQuality, 3> qualityByType(const VolumeMesh &mesh)
{
    std::array<TypeQuality, 3> q;
    for (const Cell &c : mesh.cells)
        addCell(q[static_cast<int>(c.type)], c.type, cellDihedrals(mesh, c));
    return q;
}

std::vector<std::array<TypeQuality, 3>> qualityByRegionAndType(const VolumeMesh &mesh)
{
    std::vector<std::array<TypeQuality, 3>> q(mesh.regionNames.size());
    for (std::size_t i = 0; i < mesh.cells.size() && i < mesh.cellRegion.size(); ++i) {
        const int region = mesh.cellRegion[i];
        if (region < 0 || std::size_t(region) >= q.size())
            continue;
        const Cell &c = mesh.cells[i];
        addCell(q[std::size_t(region)][static_cast<int>(c.type)], c.type, cellDihedrals(mesh, c));
    }
    return q;
}

} // namespace stratamesh
