#include "hybrid/cut_vertex_cells.h"

#include "common/union_find.h"
#include "complexity/triangle_tree.h"
#include "mesh/volume_mesh.h"
#include "volume/region_winding.h"
#include "volume/tet_quality.h"

#include <algorithm>
#include <deque>
#include <map>
#include <numeric>

namespace stratamesh {

namespace {

using namespace indexed_delaunay;

class SurfaceCrossing {
public:
    explicit SurfaceCrossing(const Model &remesh)
        : m_remesh(remesh), m_tree(remesh, allSurfaces(remesh))
    {
    }

    // Whether the closed segment meets a remesh triangle other than at its own end points
    // `skipA`, `skipB` (remesh vertex ids, or -1).
    bool segment(const Vec3 &a, const Vec3 &b, int skipA = -1, int skipB = -1) const
    {
        Box3 box;
        box.extend(a);
        box.extend(b);
        const Kernel::Segment_3 seg(cgal(a), cgal(b));
        for (const TriangleRef &t : m_tree.trianglesInBox(box)) {
            const auto &g = m_remesh.surfaceVertexToGlobal[t.surface];
            const Triangle &tri = m_remesh.surfaces[t.surface].triangles[t.triangle];
            bool touches = false;
            for (int k = 0; k < 3; ++k)
                touches = touches || g[tri[k]] == skipA || g[tri[k]] == skipB;
            if (touches)
                continue; // meets it at its end point, which is on the surface
            const Kernel::Triangle_3 k(cgal(m_remesh.vertices[g[tri[0]]]),
                                       cgal(m_remesh.vertices[g[tri[1]]]),
                                       cgal(m_remesh.vertices[g[tri[2]]]));
            if (CGAL::do_intersect(seg, k))
                return true;
        }
        return false;
    }

    // Whether a remesh vertex other than the tet's own lies in the closed tet.
    bool holdsVertex(const std::array<Vec3, 4> &q, const std::array<int, 4> &ids) const
    {
        Box3 box;
        for (const Vec3 &p : q)
            box.extend(p);
        const Kernel::Tetrahedron_3 tet(cgal(q[0]), cgal(q[1]), cgal(q[2]), cgal(q[3]));
        for (const TriangleRef &t : m_tree.trianglesInBox(box)) {
            const auto &g = m_remesh.surfaceVertexToGlobal[t.surface];
            for (int v : m_remesh.surfaces[t.surface].triangles[t.triangle]) {
                const int id = g[v];
                if (std::find(ids.begin(), ids.end(), id) != ids.end())
                    continue;
                if (!tet.has_on_unbounded_side(cgal(m_remesh.vertices[id])))
                    return true;
            }
        }
        return false;
    }

private:
    static std::vector<int> allSurfaces(const Model &m)
    {
        std::vector<int> all(m.surfaces.size());
        std::iota(all.begin(), all.end(), 0);
        return all;
    }
    const Model &m_remesh;
    TriangleTree m_tree;
};

// The points one undefined cut site may offer (its choices are its single points and pairs).
constexpr int kMostChoices = 6;

struct Built {
    std::vector<std::array<int, 4>> tets;
    bool split = false;
    Vec3 centroid = Vec3::Zero();
    double quality = -1.0; // smallest dihedral angle; -1 when a tet is not positive
};

// The faces of the convex hull of 5–8 points, each as indices ordered with the outward normal
// (exact orientation tests); empty when a point is inside the hull or four are coplanar on it
// (the thesis's invalid cells, left to the fill).
std::vector<std::array<int, 3>> hullTriangles(const std::vector<Vec3> &q)
{
    const int n = static_cast<int>(q.size());
    std::vector<Kernel::Point_3> p;
    for (const Vec3 &v : q)
        p.push_back(cgal(v));
    std::vector<std::array<int, 3>> faces;
    std::vector<char> onHull(n, 0);
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            for (int c = b + 1; c < n; ++c) {
                int above = 0, below = 0;
                for (int d = 0; d < n; ++d) {
                    if (d == a || d == b || d == c)
                        continue;
                    const auto o = CGAL::orientation(p[a], p[b], p[c], p[d]);
                    if (o == CGAL::COPLANAR)
                        return {};
                    (o == CGAL::POSITIVE ? above : below) += 1;
                }
                if (above && below)
                    continue;
                // Outward: the other points below, i.e. negative orientation with (a, b, c).
                faces.push_back(above ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
                onHull[a] = onHull[b] = onHull[c] = 1;
            }
    if (std::count(onHull.begin(), onHull.end(), 1) != n
        || static_cast<int>(faces.size()) != 2 * n - 4)
        return {};
    return faces;
}

} // namespace

std::vector<CutVertexTet> findCutVertexTets(const Delaunay &dt, const Model &remesh,
                                            const std::vector<Vec3> &sites,
                                            const std::vector<int> &pointSite,
                                            const std::vector<char> &cut, double minDihedralDegrees,
                                            std::vector<Vec3> &centroids, CutVertexStats &stats)
{
    std::vector<CutVertexTet> out;
    const int nV = static_cast<int>(remesh.vertices.size());
    const int nSites = static_cast<int>(sites.size());
    const SurfaceCrossing crossing(remesh);

    // Uncut sites linked by Delaunay edges that cross no surface share a region: one point
    // location per group.
    UnionFind groups(static_cast<int>(sites.size()));
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        const int a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
        if (!cut[a] && !cut[b] && !crossing.segment(sites[a], sites[b]))
            groups.join(a, b);
    }
    std::map<int, int> groupRegion;
    auto siteRegion = [&](int s) {
        const int root = groups.find(s);
        auto [it, fresh] = groupRegion.emplace(root, -1);
        if (fresh)
            it->second = locateRegion(remesh, sites[root]);
        return it->second;
    };

    // The cut Voronoi vertices and their regions: from an uncut site, then along Voronoi edges.
    std::map<Delaunay::Cell_handle, int> index;
    std::vector<Delaunay::Cell_handle> cells;
    std::vector<Vec3> voronoi;
    std::vector<int> region;
    const Box3 bounds = [&] {
        Box3 b;
        for (const Vec3 &p : remesh.vertices)
            b.extend(p);
        return b;
    }();
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        bool anyCut = false;
        for (int k = 0; k < 4; ++k)
            anyCut = anyCut || cut[c->vertex(k)->info()];
        if (!anyCut)
            continue;
        ++stats.candidates;
        const auto cc = CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(),
                                           c->vertex(2)->point(), c->vertex(3)->point());
        const Vec3 v(cc.x(), cc.y(), cc.z());
        int r = -1;
        if (bounds.contains(v))
            for (int k = 0; k < 4 && r < 0; ++k) {
                const int s = c->vertex(k)->info();
                if (!cut[s] && !crossing.segment(sites[s], v))
                    r = siteRegion(s);
            }
        index[c] = static_cast<int>(cells.size());
        cells.push_back(c);
        voronoi.push_back(v);
        region.push_back(bounds.contains(v) ? r : -2); // -2: outside, never reached
    }
    std::deque<int> queue;
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (region[i] >= 0)
            queue.push_back(static_cast<int>(i));
    while (!queue.empty()) {
        const int i = queue.front();
        queue.pop_front();
        for (int k = 0; k < 4; ++k) {
            auto it = index.find(cells[i]->neighbor(k));
            if (it == index.end() || region[it->second] != -1)
                continue;
            if (crossing.segment(voronoi[i], voronoi[it->second]))
                continue;
            region[it->second] = region[i];
            queue.push_back(it->second);
        }
    }

    // The points of each cut site on each region's boundary.
    std::vector<std::vector<int>> vertexSurfaces(nV);
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s)
        for (int g : remesh.surfaceVertexToGlobal[s])
            vertexSurfaces[g].push_back(static_cast<int>(s));
    std::vector<std::vector<char>> bounds_(remesh.regions.size(),
                                           std::vector<char>(remesh.surfaces.size(), 0));
    for (std::size_t r = 0; r < remesh.regions.size(); ++r)
        for (const RegionSide &side : remesh.regions[r].boundaries)
            bounds_[r][side.surface] = 1;
    std::vector<std::vector<int>> sitePoints(sites.size());
    for (int v = 0; v < nV && v < static_cast<int>(pointSite.size()); ++v)
        if (pointSite[v] >= 0)
            sitePoints[pointSite[v]].push_back(v);

    std::vector<char> sliver(cells.size(), 0);
    std::vector<std::vector<int>> members(cells.size()); // indices in out
    Vec3 pending = Vec3::Zero(); // the centroid of the cell being built, not yet kept
    auto pointAt = [&](int id) -> const Vec3 & {
        if (id < nV)
            return remesh.vertices[id];
        if (id < nV + nSites)
            return sites[id - nV];
        const std::size_t c = id - nV - nSites;
        return c < centroids.size() ? centroids[c] : pending;
    };
    // The tets of a cell on these points (4: itself, in the orientation of the sites s; 5–8:
    // split from the centroid), with their smallest dihedral angle, or no tet.
    auto build = [&](const std::vector<int> &nodes, const std::array<int, 4> &s) {
        Built b;
        if (nodes.size() == 4) {
            std::array<int, 4> t{nodes[0], nodes[1], nodes[2], nodes[3]};
            // Positively oriented like the Delaunay tet of the sites, which CGAL gives positive.
            if (tetVolume(sites[s[0]], sites[s[1]], sites[s[2]], sites[s[3]]) < 0)
                std::swap(t[0], t[1]);
            b.tets.push_back(t);
        } else {
            std::vector<Vec3> q;
            for (int id : nodes)
                q.push_back(pointAt(id));
            const auto faces = hullTriangles(q);
            if (faces.empty())
                return b;
            b.split = true;
            b.centroid = Vec3::Zero();
            for (const Vec3 &p : q)
                b.centroid += p / static_cast<double>(q.size());
            pending = b.centroid;
            const int centroid = nV + nSites + static_cast<int>(centroids.size());
            for (const auto &f : faces) // outward faces: the centroid is behind each
                b.tets.push_back({nodes[f[1]], nodes[f[0]], nodes[f[2]], centroid});
        }
        b.quality = 180.0;
        for (const auto &t : b.tets) {
            const Vec3 &p0 = pointAt(t[0]), &p1 = pointAt(t[1]), &p2 = pointAt(t[2]),
                       &p3 = pointAt(t[3]);
            const auto angles = dihedralAnglesDeg(p0, p1, p2, p3);
            b.quality = tetVolume(p0, p1, p2, p3) > 0
                            ? std::min(b.quality, *std::min_element(angles.begin(), angles.end()))
                            : -1.0;
            if (b.quality < 0)
                break;
        }
        return b;
    };
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int r = region[i];
        if (r < 0) {
            ++stats.noRegion;
            continue;
        }
        // One point per uncut site, one or two (a cell part crossed twice) per cut one. A cut
        // site with more points on the region's boundary is undefined (Fig 5.6): with one such
        // site, its one or two points are those giving the best-shaped cell (§5.4).
        std::array<int, 4> s;
        std::vector<std::vector<int>> choices(1);
        int undefined = 0;
        bool defined = true;
        for (int k = 0; k < 4; ++k) {
            s[k] = cells[i]->vertex(k)->info();
            std::vector<int> points;
            if (!cut[s[k]])
                points.push_back(nV + s[k]);
            else
                for (int v : sitePoints[s[k]])
                    for (int surface : vertexSurfaces[v])
                        if (bounds_[r][surface]) {
                            points.push_back(v);
                            break;
                        }
            const int count = static_cast<int>(points.size());
            if (count == 0 || count > kMostChoices) {
                defined = false;
                break;
            }
            std::vector<std::vector<int>> next;
            if (count <= 2) {
                for (auto c : choices) {
                    c.insert(c.end(), points.begin(), points.end());
                    next.push_back(std::move(c));
                }
            } else {
                if (++undefined > 1) {
                    defined = false;
                    break;
                }
                for (const auto &c : choices)
                    for (int x = 0; x < count; ++x)
                        for (int y = x; y < count; ++y) {
                            auto d = c;
                            d.push_back(points[x]);
                            if (y != x)
                                d.push_back(points[y]);
                            next.push_back(std::move(d));
                        }
            }
            choices = std::move(next);
        }
        if (!defined) {
            ++stats.manyPoints;
            continue;
        }
        Built best;
        for (const auto &nodes : choices) {
            Built b = build(nodes, s);
            if (best.tets.empty() || b.quality > best.quality)
                best = std::move(b);
        }
        stats.undefinedChosen += undefined;
        if (best.tets.empty() || best.quality < minDihedralDegrees) {
            ++stats.rejectedShape;
            sliver[i] = 1;
            continue;
        }
        if (best.split) {
            centroids.push_back(best.centroid);
            ++stats.split;
        }
        const std::vector<std::array<int, 4>> &tets = best.tets;
        bool clear = true;
        for (const auto &t : tets) {
            std::array<Vec3, 4> q;
            for (int k = 0; k < 4; ++k)
                q[k] = pointAt(t[k]);
            std::array<int, 4> ids;
            for (int k = 0; k < 4; ++k)
                ids[k] = t[k] < nV ? t[k] : -1;
            const Vec3 g = (q[0] + q[1] + q[2] + q[3]) / 4.0;
            clear = clear && !crossing.holdsVertex(q, ids) && !crossing.segment(voronoi[i], g);
        }
        if (!clear) {
            ++stats.rejectedSurface;
            continue;
        }
        for (const auto &t : tets) {
            members[i].push_back(static_cast<int>(out.size()));
            out.push_back({t, r, cells[i]});
        }
    }
    std::vector<char> drop(out.size(), 0);
    for (std::size_t i = 0; i < cells.size(); ++i)
        for (int k = 0; k < 4 && !members[i].empty(); ++k) {
            auto it = index.find(cells[i]->neighbor(k));
            if (it != index.end() && sliver[it->second]) {
                for (int m : members[i])
                    drop[m] = 1;
                ++stats.besideSliver;
                break;
            }
        }
    std::vector<CutVertexTet> kept;
    for (std::size_t i = 0; i < out.size(); ++i)
        if (!drop[i])
            kept.push_back(out[i]);
    return kept;
}

} // namespace stratamesh
