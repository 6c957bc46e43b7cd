#include "hybrid/vertex_dual_cells.h"

#include "complexity/indexed_delaunay.h"
#include "complexity/triangle_tree.h"
#include "volume/region_winding.h"
#include "volume/tet_quality.h"

#include <algorithm>
#include <map>
#include <numeric>

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
    return out;
}

} // namespace stratamesh
