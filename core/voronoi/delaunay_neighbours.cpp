#include "voronoi/delaunay_neighbours.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace stratamesh::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb = CGAL::Delaunay_triangulation_cell_base_3<K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;
using CellHandle = Dt::Cell_handle;

K::Point_3 toPoint(const Vec3 &v)
{
    return {v.x(), v.y(), v.z()};
}

// True when e is certainly not on the sphere through a, b, c, d: the in-sphere determinant in
// double is farther from zero than its error bound (Shewchuk 1997, "Adaptive precision
// floating-point arithmetic", insphere errboundA). Only the doubtful cases reach the exact test.
bool certainlyNotCospherical(const K::Point_3 &a, const K::Point_3 &b, const K::Point_3 &c,
                             const K::Point_3 &d, const K::Point_3 &e)
{
    const double aex = a.x() - e.x(), bex = b.x() - e.x(), cex = c.x() - e.x(), dex = d.x() - e.x();
    const double aey = a.y() - e.y(), bey = b.y() - e.y(), cey = c.y() - e.y(), dey = d.y() - e.y();
    const double aez = a.z() - e.z(), bez = b.z() - e.z(), cez = c.z() - e.z(), dez = d.z() - e.z();
    const double aexbey = aex * bey, bexaey = bex * aey, bexcey = bex * cey, cexbey = cex * bey;
    const double cexdey = cex * dey, dexcey = dex * cey, dexaey = dex * aey, aexdey = aex * dey;
    const double aexcey = aex * cey, cexaey = cex * aey, bexdey = bex * dey, dexbey = dex * bey;
    const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey,
                 da = dexaey - aexdey;
    const double ac = aexcey - cexaey, bd = bexdey - dexbey;
    const double abc = aez * bc - bez * ac + cez * ab;
    const double bcd = bez * cd - cez * bd + dez * bc;
    const double cda = cez * da + dez * ac + aez * cd;
    const double dab = dez * ab + aez * bd + bez * da;
    const double alift = aex * aex + aey * aey + aez * aez,
                 blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez,
                 dlift = dex * dex + dey * dey + dez * dez;
    const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    const auto A = [](double x) { return std::fabs(x); };
    const double permanent = ((A(cexdey) + A(dexcey)) * A(bez) + (A(dexbey) + A(bexdey)) * A(cez)
                              + (A(bexcey) + A(cexbey)) * A(dez))
                                 * alift
                             + ((A(dexaey) + A(aexdey)) * A(cez) + (A(aexcey) + A(cexaey)) * A(dez)
                                + (A(cexdey) + A(dexcey)) * A(aez))
                                   * blift
                             + ((A(aexbey) + A(bexaey)) * A(dez) + (A(bexdey) + A(dexbey)) * A(aez)
                                + (A(dexaey) + A(aexdey)) * A(bez))
                                   * clift
                             + ((A(bexcey) + A(cexbey)) * A(aez) + (A(cexaey) + A(aexcey)) * A(bez)
                                + (A(aexbey) + A(bexaey)) * A(cez))
                                   * dlift;
    constexpr double u = 0x1p-53;
    return std::fabs(det) > (16.0 + 224.0 * u) * u * permanent && permanent < 1e250;
}

// Pairs of Delaunay cells (or hull facets) lying on one sphere (or one plane): their vertices
// form a cluster whose triangulation is not unique.
struct DegenerateClusters {
    std::vector<std::pair<CellHandle, CellHandle>> links;

    // Every pair of sites inside each cluster.
    void addPairs(const Dt &dt, std::vector<std::pair<int, int>> &pairs) const
    {
        if (links.empty())
            return;
        std::map<CellHandle, int> id;
        for (const auto &[a, b] : links) {
            id.emplace(a, static_cast<int>(id.size()));
            id.emplace(b, static_cast<int>(id.size()));
        }
        std::vector<int> parent(id.size());
        std::iota(parent.begin(), parent.end(), 0);
        const auto find = [&](int x) {
            while (parent[x] != x)
                x = parent[x] = parent[parent[x]];
            return x;
        };
        for (const auto &[a, b] : links)
            parent[find(id[a])] = find(id[b]);
        std::map<int, std::vector<int>> members;
        for (const auto &[cell, index] : id)
            for (int v = 0; v <= dt.dimension(); ++v)
                if (!dt.is_infinite(cell->vertex(v)))
                    members[find(index)].push_back(cell->vertex(v)->info());
        for (auto &[root, sites] : members) {
            std::sort(sites.begin(), sites.end());
            sites.erase(std::unique(sites.begin(), sites.end()), sites.end());
            for (std::size_t a = 0; a < sites.size(); ++a)
                for (std::size_t b = a + 1; b < sites.size(); ++b)
                    pairs.emplace_back(sites[a], sites[b]);
        }
    }
};

// Degenerate adjacencies of a 3D triangulation (its Delaunay edges come from the cells).
void collectDegenerate3(const Dt &dt, DegenerateClusters &clusters)
{
    const K::Side_of_oriented_sphere_3 sideOfSphere =
        dt.geom_traits().side_of_oriented_sphere_3_object();
    const K::Orientation_3 orientation = dt.geom_traits().orientation_3_object();
    const auto sideOfCircle = dt.geom_traits().coplanar_side_of_bounded_circle_3_object();
    for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
        const CellHandle ch = c;
        const bool infinite = dt.is_infinite(ch);
        for (int f = 0; f < 4; ++f) {
            const CellHandle n = c->neighbor(f);
            if (!(ch < n))
                continue; // each adjacency once
            const bool nInfinite = dt.is_infinite(n);
            const auto opposite = n->vertex(n->index(ch));
            if (!infinite && !nInfinite) {
                if (!certainlyNotCospherical(c->vertex(0)->point(), c->vertex(1)->point(),
                                             c->vertex(2)->point(), c->vertex(3)->point(),
                                             opposite->point())
                    && sideOfSphere(c->vertex(0)->point(), c->vertex(1)->point(),
                                    c->vertex(2)->point(), c->vertex(3)->point(), opposite->point())
                           == CGAL::ON_ORIENTED_BOUNDARY)
                    clusters.links.emplace_back(ch, n);
            } else if (infinite && nInfinite) {
                // Two hull facets sharing an edge: degenerate when their four sites are cocircular.
                K::Point_3 p[3];
                int m = 0;
                for (int v = 0; v < 4; ++v)
                    if (!dt.is_infinite(c->vertex(v)))
                        p[m++] = c->vertex(v)->point();
                if (m == 3 && orientation(p[0], p[1], p[2], opposite->point()) == CGAL::COPLANAR
                    && sideOfCircle(p[0], p[1], p[2], opposite->point()) == CGAL::ON_BOUNDARY)
                    clusters.links.emplace_back(ch, n);
            }
        }
    }
}

void collectDimension2(const Dt &dt, std::vector<std::pair<int, int>> &pairs,
                       DegenerateClusters &clusters)
{
    const auto sideOfCircle = dt.geom_traits().coplanar_side_of_bounded_circle_3_object();
    for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
        const CellHandle c = f->first;
        for (int a = 0; a < 3; ++a) {
            pairs.emplace_back(c->vertex(a)->info(), c->vertex((a + 1) % 3)->info());
            const CellHandle n = c->neighbor(a);
            if (!(c < n) || dt.is_infinite(n))
                continue;
            const auto opposite = n->vertex(n->index(c));
            if (sideOfCircle(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                             opposite->point())
                == CGAL::ON_BOUNDARY)
                clusters.links.emplace_back(c, n);
        }
    }
}

void keepLowestDuplicates(Dt &dt, const std::vector<Vec3> &sites, std::vector<char> &hidden)
{
    const int n = static_cast<int>(sites.size());
    std::vector<char> present(n, 0);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        present[v->info()] = 1;
    for (int s = 0; s < n; ++s) {
        if (present[s])
            continue;
        const auto v = dt.nearest_vertex(toPoint(sites[s])); // the vertex at the same position
        if (s < v->info()) {
            hidden[v->info()] = 1;
            v->info() = s;
        } else {
            hidden[s] = 1;
        }
    }
}

} // namespace

DelaunayLists delaunayNeighbourLists(const std::vector<Vec3> &sites)
{
    DelaunayLists r;
    const int n = static_cast<int>(sites.size());
    r.hidden.assign(sites.size(), 0);
    std::vector<std::pair<K::Point_3, int>> points;
    points.reserve(n);
    for (int s = 0; s < n; ++s)
        points.emplace_back(toPoint(sites[s]), s);
    Dt dt(points.begin(), points.end());
    r.dimension = dt.dimension();
    keepLowestDuplicates(dt, sites, r.hidden);

    // Neighbours: per site, the other vertices of its cells (with repetitions), de-duplicated;
    // in parallel, the search for degenerate clusters, whose pairs are merged in afterwards.
    std::vector<std::pair<int, int>> pairs; // edges of a lower-dimensional triangulation
    DegenerateClusters clusters;
    if (r.dimension == 2) {
        collectDimension2(dt, pairs, clusters);
    } else if (r.dimension == 1) {
        for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
            pairs.emplace_back(e->first->vertex(e->second)->info(),
                               e->first->vertex(e->third)->info());
    }
    const auto extract = [&] {
        std::vector<int> rawOffsets(n + 1, 0);
        if (r.dimension == 3)
            for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
                for (int v = 0; v < 4; ++v)
                    rawOffsets[c->vertex(v)->info() + 1] += 3;
        for (const auto &[a, b] : pairs) {
            ++rawOffsets[a + 1];
            ++rawOffsets[b + 1];
        }
        std::partial_sum(rawOffsets.begin(), rawOffsets.end(), rawOffsets.begin());
        std::vector<int> raw(rawOffsets.back());
        {
            std::vector<int> fill(rawOffsets.begin(), rawOffsets.end() - 1);
            if (r.dimension == 3)
                for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
                    const int ids[4] = {c->vertex(0)->info(), c->vertex(1)->info(),
                                        c->vertex(2)->info(), c->vertex(3)->info()};
                    for (int v = 0; v < 4; ++v)
                        for (int w = 1; w < 4; ++w)
                            raw[fill[ids[v]]++] = ids[(v + w) % 4];
                }
            for (const auto &[a, b] : pairs) {
                raw[fill[a]++] = b;
                raw[fill[b]++] = a;
            }
        }
        std::vector<int> stamp(n, -1);
        r.offsets.assign(n + 1, 0);
        r.neighbours.clear();
        r.neighbours.reserve(raw.size() / 3 + 16);
        for (int i = 0; i < n; ++i) {
            for (int k = rawOffsets[i]; k < rawOffsets[i + 1]; ++k) {
                const int j = raw[k];
                if (j != i && stamp[j] != i) {
                    stamp[j] = i;
                    r.neighbours.push_back(j);
                }
            }
            r.offsets[i + 1] = static_cast<int>(r.neighbours.size());
        }
    };
    if (r.dimension == 3)
        tbb::parallel_invoke(extract, [&] { collectDegenerate3(dt, clusters); });
    else
        extract();
    std::vector<std::pair<int, int>> extra;
    clusters.addPairs(dt, extra);
    if (!extra.empty()) {
        std::vector<std::vector<int>> lists(n);
        for (int i = 0; i < n; ++i)
            lists[i].assign(r.neighbours.begin() + r.offsets[i],
                            r.neighbours.begin() + r.offsets[i + 1]);
        for (const auto &[a, b] : extra) {
            lists[a].push_back(b);
            lists[b].push_back(a);
        }
        r.neighbours.clear();
        for (int i = 0; i < n; ++i) {
            std::sort(lists[i].begin(), lists[i].end());
            lists[i].erase(std::unique(lists[i].begin(), lists[i].end()), lists[i].end());
            r.neighbours.insert(r.neighbours.end(), lists[i].begin(), lists[i].end());
            r.offsets[i + 1] = static_cast<int>(r.neighbours.size());
        }
    }
    return r;
}

} // namespace stratamesh::detail
