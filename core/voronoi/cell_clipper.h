// Intersection of one input triangle (or line segment) with the Voronoi cells it meets
// (thesis §1.2.2; Yan et al. 2009, "Isotropic remeshing with fast and exact computation of
// restricted Voronoi diagram", and Lévy & Bonneel 2013 for the propagation over
// triangle–site pairs and the security radius).
//
// The triangle is clipped by the bisectors of the site's neighbours (voronoi_neighbours.h) in
// order of distance, stopping when the next neighbour is farther than twice the farthest polygon
// vertex (no bisector beyond can cut it). Work is done in the site's frame (positions relative to
// the site) where a side test is one dot product; each computed position carries a proven bound on
// its distance to the exact symbolic point, and whenever that bound leaves the side in doubt,
// rvd_predicates.h decides exactly on the vertex's symbol. Decisions are therefore those of the
// exact (perturbed) diagram; positions are only approximate, and the symbolic diagram
// (restricted_voronoi.h) recomputes them canonically from the symbols.
// Neighbouring cells are reached through the bisectors that bound the clipped polygon, so each
// triangle–site pair is clipped once.
#pragma once

#include "voronoi/restriction_domain.h"
#include "voronoi/voronoi_neighbours.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace stratamesh::rvd {

// Support of a polygon edge: a site index ≥ 0 (the bisector with that neighbour) or −1 − e
// for edge e of the input triangle (from corner e to corner (e + 1) % 3).
inline int inputEdgeSupport(int e)
{
    return -1 - e;
}
inline int inputEdgeOf(int support)
{
    return -1 - support;
}

struct ClipVertex {
    Vec3 position;       // relative to the cell's site
    double error = 0;    // proven bound on |position − exact point|
    double u = 0, v = 0; // barycentric weights of corners 1 and 2 of the input triangle
    int out = 0;         // support of the edge from this vertex to the next one
    double norm2 = 0;    // |position|², kept for the security radius (set by the clipper)
};

// A clipped polygon: storage that only grows, so that the clipping loops write vertices after
// one capacity check per bisector instead of one per vertex (as std::vector::push_back does).
class ClipPolygon {
public:
    int size() const { return m_count; }
    bool empty() const { return m_count == 0; }
    const ClipVertex *data() const { return m_storage.data(); }
    ClipVertex *data() { return m_storage.data(); }
    const ClipVertex &operator[](int k) const { return m_storage[k]; }
    ClipVertex &operator[](int k) { return m_storage[k]; }
    const ClipVertex *begin() const { return m_storage.data(); }
    const ClipVertex *end() const { return m_storage.data() + m_count; }
    void clear() { m_count = 0; }
    // Room for n vertices; the vertices kept are left as they are.
    void reserve(int n)
    {
        if (n > static_cast<int>(m_storage.size()))
            m_storage.resize(2 * static_cast<std::size_t>(n));
    }
    // n vertices, those beyond the current count unspecified (the caller fills them).
    void resize(int n)
    {
        reserve(n);
        m_count = n;
    }
    // The next vertex, to be filled; reserve() must have made room.
    ClipVertex &append() { return m_storage[m_count++]; }
    void swap(ClipPolygon &other)
    {
        m_storage.swap(other.m_storage);
        std::swap(m_count, other.m_count);
    }

private:
    std::vector<ClipVertex> m_storage;
    int m_count = 0;
};

// A piece of a line segment inside one cell: its ends are the segment's endpoints (site −1)
// or its crossings with bisector(cell, site).
struct SegmentEnd {
    Vec3 position;
    double error = 0;
    double t = 0;  // parameter along the segment, 0 at its first point, 1 at its second
    int site = -1; // other site of the bisector, −1 for an endpoint of the segment
};

// Exact position data of an RVD vertex computed from its symbol in a canonical order, so that
// every cell and every triangle sharing the vertex gets bit-identical coordinates.
struct ComputedPoint {
    Vec3 position;
    double error = 0;
    double t = 0; // edge vertex: parameter from the lower to the higher point index
};
ComputedPoint edgeVertexPoint(const std::vector<Vec3> &points, const std::vector<Vec3> &sites,
                              int a, int b, int s0, int s1);
// Face vertex on triangle (q0, q1, q2) with sites {s0, s1, s2}; u, v barycentric of q1, q2.
ComputedPoint faceVertexPoint(const Vec3 &q0, const Vec3 &q1, const Vec3 &q2,
                              const std::vector<Vec3> &sites, int s0, int s1, int s2, double &u,
                              double &v);

// One per thread: holds scratch buffers.
class CellClipper {
public:
    CellClipper(const RestrictionDomain &domain, const VoronoiNeighbours &neighbours);

    // Intersection of triangle t with the cell of site; empty when they do not meet.
    void clipTriangle(int t, int site, ClipPolygon &polygon);

    // Calls emit(site, polygon) for every cell meeting triangle t, each once, in a
    // deterministic order. owners are the exact owners of the triangle's three points.
    template <class Emit>
    void forEachTrianglePart(int t, const int owners[3], Emit &&emit)
    {
        if (owners[0] == owners[1] && owners[1] == owners[2]) {
            wholeTriangle(t, owners[0], m_polygon);
            emit(owners[0], m_polygon);
            return;
        }
        // Sites met for this triangle are marked with a fresh stamp (no search in m_visited).
        if (++m_stamp == 0) {
            std::fill(m_marks.begin(), m_marks.end(), 0);
            m_stamp = 1;
        }
        m_visited.assign(1, owners[0]);
        m_marks[owners[0]] = m_stamp;
        for (std::size_t q = 0; q < m_visited.size(); ++q) {
            const int site = m_visited[q];
            clipTriangle(t, site, m_polygon);
            if (m_polygon.empty())
                continue;
            for (const ClipVertex &v : m_polygon)
                if (v.out >= 0 && m_marks[v.out] != m_stamp) {
                    m_marks[v.out] = m_stamp;
                    m_visited.push_back(v.out);
                }
            emit(site, m_polygon);
        }
    }

    // Calls emit(site, first, second) for the pieces of segment s in line order (from its
    // first point to its second). owners are the exact owners of its two points.
    template <class Emit>
    void forEachSegmentPart(int s, const int owners[2], Emit &&emit)
    {
        const auto &seg = m_domain.segments[s];
        SegmentEnd first{m_domain.points[seg[0]], 0, 0, -1};
        const SegmentEnd last{m_domain.points[seg[1]], 0, 1, -1};
        if (owners[0] == owners[1]) {
            emit(owners[0], first, last);
            return;
        }
        int site = owners[0];
        for (int step = 0; step <= m_delaunay.siteCount(); ++step) {
            SegmentEnd second = last;
            clipSegment(s, site, first, second);
            emit(site, first, second);
            if (second.site < 0)
                return;
            const int next = second.site;
            second.site = site; // the same point seen from the next cell
            first = second;
            site = next;
        }
        throwInconsistent(s);
    }

private:
    void wholeTriangle(int t, int site, ClipPolygon &polygon) const;
    // Clips [first, second] of segment s by the cell of site; first must stay.
    void clipSegment(int s, int site, SegmentEnd &first, SegmentEnd &second);
    int exactSide(int t, int site, const ClipPolygon &polygon, int k, int l) const;
    // The crossing of `support` with bisector(site, l), computed from its symbol.
    ClipVertex symbolicCut(int t, int site, int support, int l) const;
    [[noreturn]] void throwInconsistent(int segment) const;
    // The sites beyond the list of `site` within `radius` (VoronoiNeighbours::sitesBeyondList),
    // possibly with farther ones: the caller filters by distance. Consecutive triangles clip
    // by the same sites, so recent answers are kept.
    const std::vector<std::pair<double, int>> &sitesBeyondList(int site, double radius);

    const RestrictionDomain &m_domain;
    const VoronoiNeighbours &m_delaunay;
    ClipPolygon m_polygon, m_next;
    std::vector<int> m_visited;
    std::vector<unsigned> m_marks; // per site: the stamp of the last triangle that met it
    unsigned m_stamp = 0;
    std::vector<int> m_sides;
    std::vector<double> m_values;
    struct FartherSites {
        int site = -1;
        double radius = 0;
        std::vector<std::pair<double, int>> sites;
    };
    std::array<FartherSites, 32> m_farther;
    int m_fartherNext = 0;
};

} // namespace stratamesh::rvd
