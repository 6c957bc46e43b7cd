#include "hybrid/mixed_mesh_validity.h"

#include "common/error.h"
#include "hybrid/cell_faces.h"
#include "model/surface_edges.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace stratamesh {

namespace {

constexpr double pi = 3.14159265358979323846;

double angleDegrees(const Vec3 &u, const Vec3 &v)
{
    const double nu = u.norm(), nv = v.norm();
    if (nu == 0.0 || nv == 0.0)
        return 180.0; // a degenerate triangle: no normal, as bad as twisted
    return std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0)) * 180.0 / pi;
}

// Same cyclic order of the first three nodes of two faces with the same node set?
bool sameOrientation(const CellFace &f, const CellFace &g)
{
    for (int r = 0; r < f.size; ++r)
        if (f.nodes[0] == g.nodes[r])
            return f.nodes[1] == g.nodes[(r + 1) % f.size];
    return false;
}

struct FaceUse {
    int cell;
    CellFace face;
};

void note(MixedMeshValidity &v, const std::string &what)
{
    if (v.firstProblem.empty())
        v.firstProblem = what;
}

} // namespace

double quadWarpDegrees(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    const double ac = angleDegrees((b - a).cross(c - a), (c - a).cross(d - a));
    const double bd = angleDegrees((c - b).cross(d - b), (d - b).cross(a - b));
    return std::max(ac, bd);
}

MixedMeshValidity checkMixedMesh(const VolumeMesh &mesh, const MixedMeshCheckParams &params)
{
    validateMesh(mesh);
    const std::size_t regions = mesh.regionNames.size();
    if (!params.regionVolumes.empty() && params.regionVolumes.size() != regions)
        throw InputError("region volumes: " + std::to_string(params.regionVolumes.size())
                         + " values for " + std::to_string(regions) + " regions");
    MixedMeshValidity v;
    v.regionVolumes.assign(regions, 0.0);
    std::set<int> bad;
    auto p = [&](int k) -> const Vec3 & { return mesh.points[k]; };

    std::map<std::array<int, 4>, std::vector<FaceUse>> faces;
    for (std::size_t ci = 0; ci < mesh.cells.size(); ++ci) {
        const Cell &cell = mesh.cells[ci];
        const int c = static_cast<int>(ci);
        const int region = mesh.cellRegion[ci];
        if (region < 0) {
            ++v.cellsWithoutRegion;
            bad.insert(c);
            note(v, "cell " + std::to_string(c) + " is in no region");
        } else {
            v.regionVolumes[region] += signedVolume(mesh, cell);
        }
        for (const auto &t : cornerTets(cell))
            if (!(tetVolume(p(t[0]), p(t[1]), p(t[2]), p(t[3])) > 0.0)) {
                ++v.nonPositiveCells;
                bad.insert(c);
                note(v, std::string(cellTypeName(cell.type)) + " " + std::to_string(c)
                            + " has a corner of non-positive volume");
                break;
            }
        for (const CellFace &f : outwardFaces(cell)) {
            faces[faceKey(f)].push_back({c, f});
            if (!f.isQuad())
                continue;
            const double warp =
                quadWarpDegrees(p(f.nodes[0]), p(f.nodes[1]), p(f.nodes[2]), p(f.nodes[3]));
            v.maxQuadWarpDegrees = std::max(v.maxQuadWarpDegrees, warp);
            if (warp > 90.0) {
                ++v.twistedQuads;
                bad.insert(c);
                note(v, std::string(cellTypeName(cell.type)) + " " + std::to_string(c)
                            + " has a twisted quad face");
            } else if (warp > params.maxQuadWarpDegrees) {
                ++v.warpedQuads;
                bad.insert(c);
                note(v, std::string(cellTypeName(cell.type)) + " " + std::to_string(c)
                            + " has a quad face warped by " + std::to_string(warp) + " degrees");
            }
        }
    }

    // The surface remesh and the triangles lying on a quad face (two per quad, one per split).
    std::map<std::array<int, 3>, int> surfaceTriangles; // -> uses by cells
    for (const Triangle &t : mesh.triangles)
        surfaceTriangles[sortedTriangle(t[0], t[1], t[2])] = 0;
    std::set<std::array<int, 3>> halfQuads;
    for (const auto &[key, uses] : faces)
        if (uses.front().face.isQuad()) {
            const auto &n = uses.front().face.nodes;
            for (int s = 0; s < 4; ++s)
                halfQuads.insert(sortedTriangle(n[s], n[(s + 1) % 4], n[(s + 2) % 4]));
        }

    for (const auto &[key, uses] : faces) {
        const CellFace &f = uses.front().face;
        auto it = f.isQuad() ? surfaceTriangles.end()
                             : surfaceTriangles.find(sortedTriangle(key[0], key[1], key[2]));
        const bool onSurface = it != surfaceTriangles.end();
        if (onSurface)
            ++it->second;
        auto markAll = [&]() {
            for (const FaceUse &u : uses)
                bad.insert(u.cell);
        };
        if (uses.size() > 2) {
            ++v.overSharedFaces;
            markAll();
            note(v, "a face is shared by " + std::to_string(uses.size()) + " cells");
        } else if (uses.size() == 2) {
            if (sameOrientation(uses[0].face, uses[1].face)) {
                ++v.sameSidedFaces;
                markAll();
                note(v, "cells " + std::to_string(uses[0].cell) + " and "
                            + std::to_string(uses[1].cell) + " lie on the same side of a face");
            }
            const int r0 = mesh.cellRegion[uses[0].cell], r1 = mesh.cellRegion[uses[1].cell];
            if (r0 >= 0 && r1 >= 0 && r0 != r1 && !onSurface) {
                ++v.interfaceOffSurface;
                markAll();
                note(v, "cells " + std::to_string(uses[0].cell) + " and "
                            + std::to_string(uses[1].cell)
                            + " of two regions meet on a face that is no surface triangle");
            }
        } else if (!f.isQuad() && halfQuads.count(sortedTriangle(key[0], key[1], key[2]))) {
            ++v.nonConformalFaces;
            markAll();
            note(v, "cell " + std::to_string(uses[0].cell)
                        + " has a triangle face on half a quad face of a neighbour");
        } else if (!onSurface) {
            ++v.boundaryOffSurface;
            markAll();
            note(v, "cell " + std::to_string(uses[0].cell)
                        + " has a face on the mesh boundary that is no surface triangle");
        }
    }
    // A quad matched by two triangles is counted from the triangles' side above; the quad side
    // (a quad face of one cell) is counted there as boundaryOffSurface too.
    for (const auto &[key, uses] : surfaceTriangles)
        if (uses == 0) {
            ++v.surfaceWithoutCell;
            note(v, "a surface triangle is no cell face");
        }

    if (!params.regionVolumes.empty()) {
        double total = 0.0;
        for (double x : params.regionVolumes)
            total += std::abs(x);
        for (std::size_t r = 0; r < regions; ++r)
            if (std::abs(v.regionVolumes[r] - params.regionVolumes[r])
                > params.volumeRelativeTolerance * total) {
                ++v.regionsWithWrongVolume;
                note(v, "region " + mesh.regionNames[r] + ": cells hold "
                            + std::to_string(v.regionVolumes[r]) + ", the region "
                            + std::to_string(params.regionVolumes[r]));
            }
    }
    v.invalidCells.assign(bad.begin(), bad.end());
    return v;
}

} // namespace stratamesh
