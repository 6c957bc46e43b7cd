#include "hybrid/vertex_dual_cells.h"

#include "complexity/indexed_delaunay.h"
#include "complexity/triangle_tree.h"
#include "hybrid/cell_faces.h"
#include "model/surface_edges.h"
#include "remesh/triangle_intersections.h"
#include "volume/region_winding.h"
#include "volume/tet_quality.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace stratamesh {

namespace {

using namespace indexed_delaunay;

struct Candidate {
    std::array<int, 4> sites; // positively oriented
    bool ok = true;
};

int findRoot(std::vector<int> &parent, int i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

// The cut-cell tets whose faces cross no remesh triangle, thin-layer cell, transition pyramid to
// be, interior tet candidate or other cut-cell tet. Ids: remesh vertices, then nV + site, then
// the centroids of split cells, then the pyramid apexes.
std::vector<CutVertexTet>
keptCutTets(const Delaunay &dt, const Model &remesh, const std::vector<Vec3> &sites,
            const std::vector<int> &pointSite, const std::vector<char> &cut,
            const std::vector<Cell> &segmentCells, const std::vector<Candidate> &interior,
            const VertexDualParams &params, std::vector<Vec3> &centroids, VertexDualCells &out)
{
    std::vector<CutVertexTet> tets = findCutVertexTets(
        dt, remesh, sites, pointSite, cut, params.minDihedralDegrees, centroids, out.cut);
    const int nV = static_cast<int>(remesh.vertices.size());
    std::vector<Vec3> points = remesh.vertices;
    points.insert(points.end(), sites.begin(), sites.end());
    points.insert(points.end(), centroids.begin(), centroids.end());
    // The same four points from two Voronoi vertices: one tet.
    std::set<std::array<int, 4>> distinct;
    tets.erase(std::remove_if(tets.begin(), tets.end(),
                              [&](const CutVertexTet &t) {
                                  std::array<int, 4> key = t.nodes;
                                  std::sort(key.begin(), key.end());
                                  return !distinct.insert(key).second;
                              }),
               tets.end());
    // Each distinct face once, with the cut tets it bounds (-1: a surface, -2: another cell).
    std::map<std::array<int, 3>, std::vector<int>> owners;
    std::vector<Triangle> soup;
    std::vector<std::array<int, 3>> soupKey;
    auto add = [&](int a, int b, int c, int owner) {
        const auto key = sortedTriangle(a, b, c);
        auto [it, fresh] = owners.try_emplace(key);
        if (fresh) {
            soup.push_back({a, b, c});
            soupKey.push_back(key);
        }
        it->second.push_back(owner);
    };
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s) {
        const auto &g = remesh.surfaceVertexToGlobal[s];
        for (const Triangle &t : remesh.surfaces[s].triangles)
            add(g[t[0]], g[t[1]], g[t[2]], -1);
    }
    std::map<std::array<int, 4>, int> quadUses;
    for (const Cell &cell : segmentCells)
        for (const CellFace &f : outwardFaces(cell))
            if (f.isQuad())
                ++quadUses[faceKey(f)];
    for (const Cell &cell : segmentCells)
        for (const CellFace &f : outwardFaces(cell)) {
            const auto &n = f.nodes;
            if (!f.isQuad()) {
                add(n[0], n[1], n[2], -2);
                continue;
            }
            add(n[0], n[1], n[2], -2);
            add(n[0], n[2], n[3], -2);
            if (quadUses[faceKey(f)] != 1)
                continue;
            const Vec3 &a = points[n[0]], &b = points[n[1]], &c = points[n[2]], &d = points[n[3]];
            const Vec3 normal = (c - a).cross(d - b);
            const int apex = static_cast<int>(points.size());
            points.push_back((a + b + c + d) / 4.0
                             + normal.normalized() * params.pyramidHeightRatio
                                   * std::sqrt(0.5 * normal.norm()));
            for (int k = 0; k < 4; ++k)
                add(n[k], n[(k + 1) % 4], apex, -2);
        }
    for (const Candidate &c : interior)
        if (c.ok)
            for (int k = 0; k < 4; ++k)
                add(nV + c.sites[k], nV + c.sites[(k + 1) % 4], nV + c.sites[(k + 2) % 4], -2);
    for (std::size_t i = 0; i < tets.size(); ++i) {
        const auto &n = tets[i].nodes;
        for (int k = 0; k < 4; ++k)
            add(n[k], n[(k + 1) % 4], n[(k + 2) % 4], static_cast<int>(i));
    }
    std::vector<char> crossing(tets.size(), 0);
    for (const auto &[i, j] : findIntersectingTriangles(points, soup))
        for (int t : {i, j})
            for (int owner : owners[soupKey[t]])
                if (owner >= 0)
                    crossing[owner] = 1;
    // A face of more than two cells: they overlap, and the cut tets on it go too.
    for (const auto &[key, list] : owners)
        if (std::count_if(list.begin(), list.end(), [](int o) { return o != -1; }) > 2)
            for (int owner : list)
                if (owner >= 0)
                    crossing[owner] = 1;
    std::vector<CutVertexTet> kept;
    for (std::size_t i = 0; i < tets.size(); ++i) {
        if (crossing[i])
            ++out.cutRejectedCrossing;
        else
            kept.push_back(tets[i]);
    }
    return kept;
}

} // namespace

VertexDualCells buildVertexDualCells(const Model &remesh, const std::vector<Vec3> &sites,
                                     const std::vector<int> &pointSite,
                                     const std::vector<Cell> &segmentCells, int firstPointId,
                                     const VertexDualParams &params)
{
    VertexDualCells out;
    if (params.minDihedralDegrees >= 180.0 || sites.size() < 4)
        return out;
    std::vector<char> cut(sites.size(), 0);
    for (int s : pointSite)
        if (s >= 0 && s < static_cast<int>(sites.size()))
            cut[s] = 1;

    const Delaunay dt = triangulate(sites);
    if (dt.dimension() != 3)
        return out;

    // Candidates: finite Delaunay tets of four uncut sites, numbered for the neighbour rule.
    std::map<Delaunay::Cell_handle, int> index;
    std::vector<Candidate> candidates;
    std::vector<Delaunay::Cell_handle> handles;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        std::array<int, 4> s;
        bool interior = true;
        for (int k = 0; k < 4; ++k) {
            s[k] = c->vertex(k)->info();
            interior = interior && !cut[s[k]];
        }
        if (!interior)
            continue;
        if (tetVolume(sites[s[0]], sites[s[1]], sites[s[2]], sites[s[3]]) < 0)
            std::swap(s[0], s[1]);
        index[c] = static_cast<int>(candidates.size());
        candidates.push_back({s});
        handles.push_back(c);
    }
    out.candidates = candidates.size();

    // Slivers and their face neighbours.
    std::vector<char> sliver(candidates.size(), 0);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const auto &s = candidates[i].sites;
        const auto angles = dihedralAnglesDeg(sites[s[0]], sites[s[1]], sites[s[2]], sites[s[3]]);
        sliver[i] = *std::min_element(angles.begin(), angles.end()) < params.minDihedralDegrees;
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        bool bad = sliver[i];
        for (int k = 0; k < 4 && !bad; ++k) {
            auto it = index.find(handles[i]->neighbor(k));
            bad = it != index.end() && sliver[it->second];
        }
        if (bad) {
            candidates[i].ok = false;
            ++out.rejectedShape;
        }
    }

    // Clearance from the surfaces and from the thin-layer cells.
    std::vector<int> allSurfaces(remesh.surfaces.size());
    std::iota(allSurfaces.begin(), allSurfaces.end(), 0);
    const TriangleTree tree(remesh, allSurfaces);
    std::vector<Box3> cellBoxes;
    for (const Cell &cell : segmentCells) {
        Box3 b;
        for (int k = 0; k < cell.size(); ++k)
            b.extend(remesh.vertices[cell.nodes[k]]);
        cellBoxes.push_back(b);
    }
    for (Candidate &c : candidates) {
        if (!c.ok)
            continue;
        std::array<Vec3, 4> q;
        Vec3 g = Vec3::Zero();
        for (int k = 0; k < 4; ++k)
            g += sites[c.sites[k]] / 4.0;
        Box3 box;
        for (int k = 0; k < 4; ++k) {
            q[k] = g + (1.0 + params.clearance) * (sites[c.sites[k]] - g);
            box.extend(q[k]);
        }
        const Kernel::Tetrahedron_3 tet(cgal(q[0]), cgal(q[1]), cgal(q[2]), cgal(q[3]));
        bool near = false;
        for (const TriangleRef &t : tree.trianglesInBox(box)) {
            const Surface &s = remesh.surfaces[t.surface];
            const Triangle &tri = s.triangles[t.triangle];
            const Kernel::Triangle_3 k(cgal(s.vertices[tri[0]]), cgal(s.vertices[tri[1]]),
                                       cgal(s.vertices[tri[2]]));
            if (CGAL::do_intersect(tet, k)) {
                near = true;
                break;
            }
        }
        if (near) {
            c.ok = false;
            ++out.rejectedNearSurface;
            continue;
        }
        // Segment-dual cells are few (thin layers only): a linear scan is cheaper than a tree.
        for (const Box3 &b : cellBoxes)
            if (b.intersects(box)) {
                c.ok = false;
                ++out.rejectedNearCells;
                break;
            }
    }

    std::vector<Vec3> centroids; // of the cells split from their centroid
    const std::vector<CutVertexTet> cutTets =
        !params.fillCutCells ? keptCutTets(dt, remesh, sites, pointSite, cut, segmentCells,
                                           candidates, params, centroids, out)
                             : std::vector<CutVertexTet>{};

    // Kept tets do not meet the surfaces, so each group linked by shared sites lies in one region:
    // one point location per group.
    std::vector<int> parent(sites.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const Candidate &c : candidates)
        if (c.ok)
            for (int k = 1; k < 4; ++k)
                parent[findRoot(parent, c.sites[k])] = findRoot(parent, c.sites[0]);
    std::map<int, int> groupRegion;
    std::vector<int> pointOf(sites.size(), -1);
    for (const Candidate &c : candidates) {
        if (!c.ok)
            continue;
        const int root = findRoot(parent, c.sites[0]);
        auto [it, fresh] = groupRegion.emplace(root, -1);
        if (fresh) {
            const Vec3 g =
                (sites[c.sites[0]] + sites[c.sites[1]] + sites[c.sites[2]] + sites[c.sites[3]])
                / 4.0;
            it->second = locateRegion(remesh, g);
        }
        if (it->second < 0) {
            ++out.rejectedOutside;
            continue;
        }
        Cell cell = Cell::tet(0, 0, 0, 0);
        for (int k = 0; k < 4; ++k) {
            int &id = pointOf[c.sites[k]];
            if (id < 0) {
                id = firstPointId + static_cast<int>(out.points.size());
                out.points.push_back(sites[c.sites[k]]);
            }
            cell.nodes[k] = id;
        }
        out.cells.push_back(cell);
        out.region.push_back(it->second);
    }
    const int nV = static_cast<int>(remesh.vertices.size());
    std::vector<int> centroidOf(centroids.size(), -1);
    for (const CutVertexTet &t : cutTets) {
        Cell cell = Cell::tet(0, 0, 0, 0);
        for (int k = 0; k < 4; ++k) {
            if (t.nodes[k] < nV) {
                cell.nodes[k] = t.nodes[k];
                continue;
            }
            const int nSites = static_cast<int>(sites.size());
            const bool site = t.nodes[k] < nV + nSites;
            int &id = site ? pointOf[t.nodes[k] - nV] : centroidOf[t.nodes[k] - nV - nSites];
            if (id < 0) {
                id = firstPointId + static_cast<int>(out.points.size());
                out.points.push_back(site ? sites[t.nodes[k] - nV]
                                          : centroids[t.nodes[k] - nV - nSites]);
            }
            cell.nodes[k] = id;
        }
        out.cells.push_back(cell);
        out.region.push_back(t.region);
        ++out.cutKept;
        out.cutSplitKept += *std::max_element(t.nodes.begin(), t.nodes.end())
                            >= nV + static_cast<int>(sites.size());
    }
    return out;
}

} // namespace stratamesh
