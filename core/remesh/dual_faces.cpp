#include "remesh/dual_faces.h"

#include "quality/triangle_quality.h"

#include <algorithm>
#include <climits>
#include <unordered_map>

namespace stratamesh {

namespace {

constexpr int kUnknown = INT_MIN;

std::uint64_t pairKey(int a, int b)
{
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32)
           | static_cast<std::uint32_t>(b);
}

// A maximal run of a piece's boundary with one neighbour: a piece (label ≥ 0) across a
// bisector, or a line component b (label −1 − b).
struct Arc {
    int from, to;
    int label;
};

class Builder {
public:
    Builder(const RestrictionDomain &domain, const RestrictedVoronoiDiagram &cells,
            const CellComponents &cc, const CellPoints &points, DualFaceCounts &counts)
        : m_domain(domain), m_cells(cells), m_cc(cc), m_points(points), m_counts(counts),
          m_segments(domain)
    {
        for (int f = 0; f < static_cast<int>(cells.polygons.size()); ++f)
            m_facetOf.emplace(pairKey(cells.polygons[f].triangle, cells.polygons[f].site), f);
    }

    std::vector<OutputTriangle> run(Progress &progress)
    {
        progress.tick(0.0, "attachments");
        attachMultiPointPieces();
        progress.tick(0.5, "triangles");
        vertexTriangles();
        return std::move(m_triangles);
    }

private:
    int attached(int piece, int vertex) const
    {
        const std::vector<int> &pts = m_points.piecePoints[piece];
        if (pts.size() == 1)
            return pts.front();
        if (pts.empty())
            return -1;
        auto it = m_attach.find(pairKey(piece, vertex));
        return it != m_attach.end() ? it->second : nearest(pts, vertex);
    }

    int nearest(const std::vector<int> &pts, int vertex) const
    {
        const Vec3 &x = m_cells.vertices[vertex].position;
        int best = pts.front();
        for (int p : pts)
            if ((m_points.points[p].position - x).squaredNorm()
                < (m_points.points[best].position - x).squaredNorm())
                best = p;
        return best;
    }

    int linePointOf(int label) const
    {
        return label < 0 && label != kUnknown ? m_points.lineComponentPoint[-1 - label] : -1;
    }

    // Boundary loops of one piece, as arcs, counter-clockwise around the input normal.
    std::vector<std::vector<Arc>> loopsOf(const std::vector<int> &facets) const
    {
        struct Edge {
            int from, to, label;
        };
        std::vector<Edge> edges;
        for (int f : facets) {
            const RvdPolygon &facet = m_cells.polygons[f];
            const Triangle &tri = m_domain.triangles[facet.triangle];
            for (int k = 0; k < facet.count; ++k) {
                const int support = m_cells.polygonSupports[facet.first + k];
                const int from = m_cells.polygonVertices[facet.first + k];
                const int to = m_cells.polygonVertices[facet.first + (k + 1) % facet.count];
                if (support >= 0) {
                    auto it = m_facetOf.find(pairKey(facet.triangle, support));
                    edges.push_back(
                        {from, to, it == m_facetOf.end() ? kUnknown : m_cc.facetPiece[it->second]});
                    continue;
                }
                const int e = -1 - support;
                const int s = m_segments.find(tri[e], tri[(e + 1) % 3]);
                if (s < 0)
                    continue; // inside the piece
                const int l = m_cc.linePieceOf(s, facet.site);
                edges.push_back({from, to, l >= 0 ? -1 - m_cc.linePieceComponent[l] : kUnknown});
            }
        }
        std::unordered_map<int, std::vector<int>> byFrom;
        for (int i = 0; i < static_cast<int>(edges.size()); ++i)
            byFrom[edges[i].from].push_back(i);
        std::vector<char> used(edges.size(), 0);
        std::vector<std::vector<Arc>> loops;
        for (int start = 0; start < static_cast<int>(edges.size()); ++start) {
            if (used[start])
                continue;
            std::vector<Edge> loop;
            for (int e = start; e >= 0 && !used[e];) {
                used[e] = 1;
                loop.push_back(edges[e]);
                int next = -1;
                for (int candidate : byFrom[edges[e].to])
                    if (!used[candidate]) {
                        next = candidate;
                        break;
                    }
                e = next;
            }
            // Rotate to start at a change of neighbour, then group runs into arcs.
            const std::size_t n = loop.size();
            std::size_t first = 0;
            while (first < n && loop[first].label == loop[(first + n - 1) % n].label)
                ++first;
            if (first == n)
                first = 0;
            std::vector<Arc> arcs;
            for (std::size_t i = 0; i < n; ++i) {
                const Edge &edge = loop[(first + i) % n];
                if (!arcs.empty() && arcs.back().label == edge.label && arcs.back().to == edge.from)
                    arcs.back().to = edge.to;
                else
                    arcs.push_back({edge.from, edge.to, edge.label});
            }
            loops.push_back(std::move(arcs));
        }
        return loops;
    }

    void attachMultiPointPieces()
    {
        const int np = static_cast<int>(m_cc.pieceSite.size());
        std::vector<std::vector<int>> facetsOfPiece(np);
        for (int f = 0; f < static_cast<int>(m_cells.polygons.size()); ++f)
            if (m_points.piecePoints[m_cc.facetPiece[f]].size() > 1)
                facetsOfPiece[m_cc.facetPiece[f]].push_back(f);
        for (int p = 0; p < np; ++p) {
            if (facetsOfPiece[p].empty())
                continue;
            const std::vector<std::vector<Arc>> loops = loopsOf(facetsOfPiece[p]);
            for (const std::vector<Arc> &loop : loops)
                attachLoop(p, loop);
            for (const std::vector<Arc> &loop : loops)
                m_pieceLoops.push_back({p, loop});
        }
        for (const auto &[p, loop] : m_pieceLoops)
            arcPolygons(p, loop);
    }

    void attachLoop(int piece, const std::vector<Arc> &loop)
    {
        const std::vector<int> &pts = m_points.piecePoints[piece];
        const int n = static_cast<int>(loop.size());
        std::vector<int> lineArcs;
        for (int i = 0; i < n; ++i)
            if (linePointOf(loop[i].label) >= 0)
                lineArcs.push_back(i);
        if (lineArcs.empty()) {
            for (const Arc &a : loop)
                m_attach[pairKey(piece, a.from)] = nearest(pts, a.from);
            return;
        }
        for (int i : lineArcs) {
            m_attach[pairKey(piece, loop[i].from)] = linePointOf(loop[i].label);
            m_attach[pairKey(piece, loop[i].to)] = linePointOf(loop[i].label);
        }
        // Chains of Voronoi arcs between consecutive line arcs: switch once, where the arc ends
        // become nearer to the next line's point.
        for (std::size_t j = 0; j < lineArcs.size(); ++j) {
            const int a = lineArcs[j];
            const int b = lineArcs[(j + 1) % lineArcs.size()];
            const int pa = linePointOf(loop[a].label), pb = linePointOf(loop[b].label);
            std::vector<int> ends; // arc ends strictly between the two line arcs
            for (int i = (a + 1) % n; i != b; i = (i + 1) % n)
                if (i != a && (i + 1) % n != b)
                    ends.push_back(loop[i].to);
            bool switched = pa == pb;
            for (int v : ends) {
                if (!switched) {
                    const Vec3 &x = m_cells.vertices[v].position;
                    switched = (m_points.points[pb].position - x).squaredNorm()
                               < (m_points.points[pa].position - x).squaredNorm();
                }
                m_attach[pairKey(piece, v)] = switched ? pb : pa;
            }
        }
    }

    // Voronoi arcs whose two ends see different points on one side become polygons.
    void arcPolygons(int piece, const std::vector<Arc> &loop)
    {
        const int site = m_cc.pieceSite[piece];
        for (const Arc &arc : loop) {
            if (arc.label < 0)
                continue;
            const int other = arc.label;
            if (m_points.piecePoints[other].size() > 1 && m_cc.pieceSite[other] < site)
                continue; // the other side emits it
            const int p1 = attached(piece, arc.from), p2 = attached(piece, arc.to);
            const int q1 = attached(other, arc.from), q2 = attached(other, arc.to);
            if (p1 == p2 && q1 == q2)
                continue;
            emitPolygon({p1, q1, q2, p2}, m_cc.pieceSurface[piece], true);
        }
    }

    void vertexTriangles()
    {
        const int nv = static_cast<int>(m_cells.vertices.size());
        std::vector<long long> occurrence(3 * static_cast<std::size_t>(nv), -1); // facet * 1024 + k
        std::vector<unsigned char> count(nv, 0);
        for (int f = 0; f < static_cast<int>(m_cells.polygons.size()); ++f) {
            const RvdPolygon &facet = m_cells.polygons[f];
            for (int k = 0; k < facet.count; ++k) {
                const int v = m_cells.polygonVertices[facet.first + k];
                if (m_cells.vertices[v].symbol.kind != RvdVertexKind::FaceVoronoiEdge)
                    continue;
                if (count[v] < 3)
                    occurrence[3 * v + count[v]] = f * 1024LL + k;
                ++count[v];
            }
        }
        for (int v = 0; v < nv; ++v) {
            if (m_cells.vertices[v].symbol.kind != RvdVertexKind::FaceVoronoiEdge)
                continue;
            if (count[v] != 3) {
                ++m_counts.incompleteVertices;
                continue;
            }
            int facetAt[3], inSite[3], site[3];
            for (int i = 0; i < 3; ++i) {
                const int f = static_cast<int>(occurrence[3 * v + i] / 1024),
                          k = static_cast<int>(occurrence[3 * v + i] % 1024);
                const RvdPolygon &facet = m_cells.polygons[f];
                facetAt[i] = f;
                site[i] = facet.site;
                inSite[i] =
                    m_cells.polygonSupports[facet.first + (k + facet.count - 1) % facet.count];
            }
            // Counter-clockwise: from a cell to the one across its incoming edge.
            int order[3] = {0, -1, -1};
            for (int step = 1; step < 3; ++step)
                for (int i = 0; i < 3; ++i)
                    if (site[i] == inSite[order[step - 1]])
                        order[step] = i;
            if (order[1] < 0 || order[2] < 0) {
                ++m_counts.incompleteVertices;
                continue;
            }
            std::vector<int> poly;
            for (int i : order)
                poly.push_back(attached(m_cc.facetPiece[facetAt[i]], v));
            emitPolygon(poly, m_domain.triangleSurface[m_cells.polygons[facetAt[0]].triangle],
                        false);
        }
    }

    void emitPolygon(std::vector<int> poly, int surface, bool fromArc)
    {
        std::vector<int> clean;
        for (int p : poly)
            if (p >= 0 && (clean.empty() || clean.back() != p))
                clean.push_back(p);
        while (clean.size() > 1 && clean.front() == clean.back())
            clean.pop_back();
        std::vector<int> sorted = clean;
        std::sort(sorted.begin(), sorted.end());
        if (clean.size() < 3 || std::unique(sorted.begin(), sorted.end()) != sorted.end()) {
            ++m_counts.collapsedFaces;
            return;
        }
        ++(fromArc ? m_counts.arcPolygons : m_counts.vertexTriangles);
        if (clean.size() == 3) {
            m_triangles.push_back({{clean[0], clean[1], clean[2]}, surface});
            return;
        }
        // A quad: the diagonal giving the better smaller quality.
        auto q = [&](int a, int b, int c) {
            return triangleQuality(m_points.points[a].position, m_points.points[b].position,
                                   m_points.points[c].position);
        };
        const double d02 =
            std::min(q(clean[0], clean[1], clean[2]), q(clean[0], clean[2], clean[3]));
        const double d13 =
            std::min(q(clean[1], clean[2], clean[3]), q(clean[1], clean[3], clean[0]));
        if (d02 >= d13) {
            m_triangles.push_back({{clean[0], clean[1], clean[2]}, surface});
            m_triangles.push_back({{clean[0], clean[2], clean[3]}, surface});
        } else {
            m_triangles.push_back({{clean[1], clean[2], clean[3]}, surface});
            m_triangles.push_back({{clean[1], clean[3], clean[0]}, surface});
        }
    }

    const RestrictionDomain &m_domain;
    const RestrictedVoronoiDiagram &m_cells;
    const CellComponents &m_cc;
    const CellPoints &m_points;
    DualFaceCounts &m_counts;
    SegmentIndex m_segments;
    std::unordered_map<std::uint64_t, int> m_facetOf;
    std::unordered_map<std::uint64_t, int> m_attach;
    std::vector<std::pair<int, std::vector<Arc>>> m_pieceLoops;
    std::vector<OutputTriangle> m_triangles;
};

} // namespace

std::vector<OutputTriangle> buildDualFaces(const RestrictionDomain &domain,
                                           const RestrictedVoronoiDiagram &cells,
                                           const CellComponents &components,
                                           const CellPoints &points, DualFaceCounts &counts,
                                           Progress &progress)
{
    return Builder(domain, cells, components, points, counts).run(progress);
}

} // namespace stratamesh
