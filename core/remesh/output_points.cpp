#include "remesh/output_points.h"
#include "common/translate_noop.h"

#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

namespace stratamesh {

namespace {

using K = CGAL::Simple_cartesian<double>;
K::Point_3 cg(const Vec3 &v)
{
    return K::Point_3(v.x(), v.y(), v.z());
}
Vec3 eg(const K::Point_3 &p)
{
    return Vec3(p.x(), p.y(), p.z());
}

struct Segment3 {
    Vec3 a, b;
};
struct Triangle3 {
    Vec3 a, b, c;
};

// The model part a point stands for: pieces of lines, and facets of cells without lines.
struct Part {
    std::vector<Segment3> segments;
    std::vector<Triangle3> triangles;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::max());
    void grow(const Vec3 &p)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    void append(const Part &o)
    {
        segments.insert(segments.end(), o.segments.begin(), o.segments.end());
        triangles.insert(triangles.end(), o.triangles.begin(), o.triangles.end());
        grow(o.lo);
        grow(o.hi);
    }
};

Vec3 closestOn(const Part &part, const Vec3 &x)
{
    double best = std::numeric_limits<double>::max();
    Vec3 result = x;
    for (const Segment3 &s : part.segments) {
        if (s.a == s.b)
            continue;
        const Vec3 d = s.b - s.a;
        const double t = std::clamp((x - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
        const Vec3 p = s.a + t * d;
        const double dist = (p - x).squaredNorm();
        if (dist < best) {
            best = dist;
            result = p;
        }
    }
    for (const Triangle3 &t : part.triangles) {
        const K::Triangle_3 tri(cg(t.a), cg(t.b), cg(t.c));
        if (tri.is_degenerate())
            continue;
        const K::Point_3 p = tri.supporting_plane().projection(cg(x));
        Vec3 q = eg(p);
        // Inside by the signs of the edge normals: Triangle_3::has_on in Simple_cartesian<double>
        // asks an exact barycentric sum, so points well inside were taken for outside.
        const Vec3 n = (t.b - t.a).cross(t.c - t.a);
        const bool inside = n.dot((t.b - t.a).cross(q - t.a)) >= 0
                            && n.dot((t.c - t.b).cross(q - t.b)) >= 0
                            && n.dot((t.a - t.c).cross(q - t.c)) >= 0;
        if (!inside) {
            // Outside: the nearest point is on an edge.
            double edgeBest = std::numeric_limits<double>::max();
            for (const auto &[u, v] :
                 {std::pair{t.a, t.b}, std::pair{t.b, t.c}, std::pair{t.c, t.a}}) {
                const Vec3 d = v - u;
                const double s = d.squaredNorm() > 0
                                     ? std::clamp((x - u).dot(d) / d.squaredNorm(), 0.0, 1.0)
                                     : 0.0;
                const Vec3 e = u + s * d;
                if ((e - x).squaredNorm() < edgeBest) {
                    edgeBest = (e - x).squaredNorm();
                    q = e;
                }
            }
        }
        const double dist = (q - x).squaredNorm();
        if (dist < best) {
            best = dist;
            result = q;
        }
    }
    return result;
}

// Smallest distance between two parts: exact between segments, and from every vertex of one
// part to the other otherwise (the parts are small pieces of one Voronoi cell).
double partDistance(const Part &a, const Part &b, double cutoff)
{
    const Vec3 gap = (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(Vec3::Zero());
    if (gap.norm() >= cutoff)
        return gap.norm();
    double best = std::numeric_limits<double>::max();
    for (const Segment3 &s : a.segments)
        for (const Segment3 &t : b.segments)
            best =
                std::min(best, std::sqrt(CGAL::squared_distance(K::Segment_3(cg(s.a), cg(s.b)),
                                                                K::Segment_3(cg(t.a), cg(t.b)))));
    auto vertexDistances = [&](const Part &from, const Part &to) {
        std::vector<Vec3> vs;
        for (const Segment3 &s : from.segments)
            vs.insert(vs.end(), {s.a, s.b});
        for (const Triangle3 &t : from.triangles)
            vs.insert(vs.end(), {t.a, t.b, t.c});
        for (const Vec3 &v : vs)
            best = std::min(best, (closestOn(to, v) - v).norm());
    };
    vertexDistances(a, b);
    vertexDistances(b, a);
    return best;
}

class PointSet {
public:
    int add(OutputPoint p, Part part)
    {
        m_points.push_back(std::move(p));
        m_parts.push_back(std::move(part));
        m_parent.push_back(static_cast<int>(m_parent.size()));
        return static_cast<int>(m_points.size()) - 1;
    }
    int find(int x)
    {
        while (m_parent[x] != x)
            x = m_parent[x] = m_parent[m_parent[x]];
        return x;
    }
    // Merges the group into its first member, at `position`; returns the representative.
    int merge(const std::vector<int> &group, const Vec3 &position, PointOrigin origin)
    {
        const int root = find(group.front());
        for (std::size_t i = 1; i < group.size(); ++i) {
            const int r = find(group[i]);
            if (r == root)
                continue;
            m_parent[r] = root;
            mergeSortedIds(m_points[root].surfaces, m_points[r].surfaces);
            mergeSortedIds(m_points[root].lines, m_points[r].lines);
            mergeSortedIds(m_points[root].corners, m_points[r].corners);
            m_parts[root].append(m_parts[r]);
        }
        m_points[root].position = position;
        m_points[root].origin = origin;
        return root;
    }
    OutputPoint &point(int i) { return m_points[i]; }
    void setPart(int i, Part part) { m_parts[i] = std::move(part); }
    const Part &part(int i) const { return m_parts[i]; }
    int size() const { return static_cast<int>(m_points.size()); }

private:
    std::vector<OutputPoint> m_points;
    std::vector<Part> m_parts;
    std::vector<int> m_parent;
};

std::vector<EntityRef> refsOf(const Model &model, const OutputPoint &p)
{
    std::vector<EntityRef> refs;
    for (int s : p.surfaces)
        addUnique(refs, surfaceRef(model, s));
    for (int l : p.lines)
        addUnique(refs, lineRef(model, l));
    for (int c : p.corners)
        addUnique(refs, cornerRef(model, c));
    return refs;
}

LedgerRecord mergeRecord(LedgerKind kind, const Model &model, PointSet &set,
                         const std::vector<Vec3> &before, int root, double size,
                         const std::string &meaning, const char *note)
{
    LedgerRecord r;
    r.kind = kind;
    r.inputs = refsOf(model, set.point(root));
    r.position = set.point(root).position;
    r.size = size;
    if (meaning == "distance" && size == 0.0)
        for (const Vec3 &b : before)
            r.size = std::max(r.size, (b - r.position).norm());
    r.sizeMeaning = meaning;
    setNote(r, {note, {}});
    return r;
}

Vec3 mean(const std::vector<Vec3> &v)
{
    Vec3 m = Vec3::Zero();
    for (const Vec3 &x : v)
        m += x;
    return v.empty() ? m : Vec3(m / static_cast<double>(v.size()));
}

} // namespace

CellPoints computeCellPoints(const Model &model, const RestrictionDomain &domain,
                             const RestrictedVoronoiDiagram &cells, const CellComponents &cc,
                             const CellPointsParams &params, SimplificationLedger &ledger,
                             Progress &progress)
{
    const double dResolution = params.dResolution;
    PointSet set;
    const int nb = static_cast<int>(cc.lineComponentSite.size());
    const int ncell = static_cast<int>(cc.cellSite.size());
    std::vector<int> bcPoint(nb, -1), cellPoint(ncell, -1);

    // (1)+(2): one point per line component, at its corner, or its corners merged, or on it.
    progress.tick(0.0, "points on lines");
    for (int b = 0; b < nb; ++b) {
        if (b % 256 == 0)
            progress.tick(0.3 * b / nb, "points on lines");
        OutputPoint p;
        p.site = cc.lineComponentSite[b];
        Part part;
        double length = 0.0;
        Vec3 centroid = Vec3::Zero();
        for (int l : cc.lineComponentPieces[b]) {
            const RvdLinePiece &piece = cells.linePieces[l];
            const Vec3 &a = cells.vertices[piece.vertices[0]].position,
                       &c = cells.vertices[piece.vertices[1]].position;
            part.segments.push_back({a, c});
            part.grow(a);
            part.grow(c);
            const double len = (c - a).norm();
            length += len;
            centroid += 0.5 * len * (a + c);
            const int line = domain.segmentLine[piece.segment];
            p.lines.push_back(line);
            if (line >= 0 && line < static_cast<int>(model.lines.size()))
                p.surfaces.insert(p.surfaces.end(), model.lines[line].surfaces.begin(),
                                  model.lines[line].surfaces.end());
        }
        std::sort(p.lines.begin(), p.lines.end());
        p.lines.erase(std::unique(p.lines.begin(), p.lines.end()), p.lines.end());
        std::sort(p.surfaces.begin(), p.surfaces.end());
        p.surfaces.erase(std::unique(p.surfaces.begin(), p.surfaces.end()), p.surfaces.end());
        p.corners = cc.lineComponentCorners[b];
        std::sort(p.corners.begin(), p.corners.end());
        std::vector<Vec3> cornerPositions;
        for (int c : p.corners)
            cornerPositions.push_back(domain.points[domain.corners[c]]);
        if (cornerPositions.size() == 1) {
            p.origin = PointOrigin::Corner;
            p.position = cornerPositions.front();
        } else if (cornerPositions.size() > 1) {
            p.origin = PointOrigin::Corner;
            p.position = closestOn(part, mean(cornerPositions));
        } else {
            p.origin = PointOrigin::Line;
            p.position =
                closestOn(part, length > 0 ? Vec3(centroid / length) : part.segments.front().a);
        }
        bcPoint[b] = set.add(p, part);
        if (cornerPositions.size() > 1)
            ledger.push_back(mergeRecord(
                LedgerKind::CornerMerge, model, set, cornerPositions, bcPoint[b], 0.0, "distance",
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "corners of one Voronoi cell joined by a line merged (Fig 4.6b)")));
    }

    // (1) cell components without lines: centroid projected onto the component.
    progress.tick(0.3, "points on surfaces");
    for (int c = 0; c < ncell; ++c) {
        if (!cc.cellLineComponents[c].empty() || cc.cellPieces[c].empty())
            continue;
        OutputPoint p;
        p.site = cc.cellSite[c];
        p.origin = PointOrigin::Surface;
        cellPoint[c] = set.add(p, {});
    }
    {
        std::vector<Part> parts(ncell);
        std::vector<Vec3> moment(ncell, Vec3::Zero());
        std::vector<double> area(ncell, 0.0);
        std::vector<std::vector<int>> surfaces(ncell);
        for (int f = 0; f < static_cast<int>(cells.polygons.size()); ++f) {
            const int c = cc.pieceCell[cc.facetPiece[f]];
            if (cellPoint[c] < 0)
                continue;
            const RvdPolygon &facet = cells.polygons[f];
            const Vec3 &o = cells.vertices[cells.polygonVertices[facet.first]].position;
            for (int k = 1; k + 1 < facet.count; ++k) {
                const Vec3 &a = cells.vertices[cells.polygonVertices[facet.first + k]].position;
                const Vec3 &b = cells.vertices[cells.polygonVertices[facet.first + k + 1]].position;
                const double ar = 0.5 * (a - o).cross(b - o).norm();
                area[c] += ar;
                moment[c] += ar * (o + a + b) / 3.0;
                parts[c].triangles.push_back({o, a, b});
            }
            for (int k = 0; k < facet.count; ++k)
                parts[c].grow(cells.vertices[cells.polygonVertices[facet.first + k]].position);
            surfaces[c].push_back(domain.triangleSurface[facet.triangle]);
        }
        for (int c = 0; c < ncell; ++c) {
            if (cellPoint[c] < 0)
                continue;
            OutputPoint &p = set.point(cellPoint[c]);
            std::sort(surfaces[c].begin(), surfaces[c].end());
            surfaces[c].erase(std::unique(surfaces[c].begin(), surfaces[c].end()),
                              surfaces[c].end());
            p.surfaces = surfaces[c];
            const Vec3 centroid =
                area[c] > 0 ? Vec3(moment[c] / area[c])
                            : (parts[c].triangles.empty() ? Vec3::Zero() : parts[c].triangles[0].a);
            p.position = closestOn(parts[c], centroid);
            set.setPart(cellPoint[c], std::move(parts[c]));
        }
    }

    // (3) cell components with more than two points: merged onto the component.
    progress.tick(0.6, "merges");
    for (int c = 0; c < ncell; ++c) {
        std::vector<int> roots;
        for (int b : cc.cellLineComponents[c])
            roots.push_back(set.find(bcPoint[b]));
        std::sort(roots.begin(), roots.end());
        roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
        if (roots.size() <= 2)
            continue;
        if (params.mergeAllExtraPoints) {
            std::vector<Vec3> before;
            for (int r : roots)
                before.push_back(set.point(r).position);
            Part all;
            for (int r : roots)
                all.append(set.part(r));
            const int root = set.merge(roots, closestOn(all, mean(before)), PointOrigin::Line);
            ledger.push_back(mergeRecord(
                LedgerKind::MultiPointMerge, model, set, before, root, 0.0, "distance",
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "a cell component with more than two points: points merged (Fig 4.6a)")));
            continue;
        }
        // Merge the two points whose model parts are closest, until two are left: the same
        // guarantee (1 or 2 points per component) for the smallest change of the model.
        while (roots.size() > 2) {
            double best = std::numeric_limits<double>::max();
            std::size_t bi = 0, bj = 1;
            for (std::size_t i = 0; i < roots.size(); ++i)
                for (std::size_t j = i + 1; j < roots.size(); ++j) {
                    const double d = partDistance(set.part(roots[i]), set.part(roots[j]), best);
                    if (d < best) {
                        best = d;
                        bi = i;
                        bj = j;
                    }
                }
            const std::vector<Vec3> before{set.point(roots[bi]).position,
                                           set.point(roots[bj]).position};
            Part both = set.part(roots[bi]);
            both.append(set.part(roots[bj]));
            const PointOrigin origin =
                std::min(set.point(roots[bi]).origin, set.point(roots[bj]).origin);
            const int root =
                set.merge({roots[bi], roots[bj]}, closestOn(both, mean(before)), origin);
            ledger.push_back(mergeRecord(
                LedgerKind::MultiPointMerge, model, set, before, root, best, "distance",
                QT_TRANSLATE_NOOP("stratamesh::Core", "a cell component with more than two points: "
                                                      "its two closest merged (Fig 4.6a)")));
            roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(bj));
            roots[bi] = root;
        }
    }

    // (4) points of one cell whose model parts are closer than d_resolution.
    if (dResolution > 0.0) {
        std::map<int, std::vector<int>> bySite;
        for (int i = 0; i < set.size(); ++i)
            if (set.find(i) == i)
                bySite[set.point(i).site].push_back(i);
        for (auto &[site, points] : bySite) {
            for (std::size_t i = 0; i < points.size(); ++i)
                for (std::size_t j = i + 1; j < points.size(); ++j) {
                    const int a = set.find(points[i]), b = set.find(points[j]);
                    if (a == b)
                        continue;
                    const double d = partDistance(set.part(a), set.part(b), dResolution);
                    if (d >= dResolution)
                        continue;
                    const std::vector<Vec3> before{set.point(a).position, set.point(b).position};
                    const PointOrigin origin = std::min(set.point(a).origin, set.point(b).origin);
                    const int root = set.merge({a, b}, mean(before), origin);
                    ledger.push_back(mergeRecord(
                        LedgerKind::CloseFeatureMerge, model, set, before, root, d, "distance",
                        QT_TRANSLATE_NOOP(
                            "stratamesh::Core",
                            "model parts closer than d_resolution merged (Fig 4.7)")));
                }
        }
    }

    // Renumber the representatives.
    CellPoints result;
    std::vector<int> index(set.size(), -1);
    for (int i = 0; i < set.size(); ++i)
        if (set.find(i) == i) {
            index[i] = static_cast<int>(result.points.size());
            result.points.push_back(set.point(i));
        }
    result.lineComponentPoint.resize(nb);
    for (int b = 0; b < nb; ++b)
        result.lineComponentPoint[b] = index[set.find(bcPoint[b])];
    result.cellPoint.assign(ncell, -1);
    for (int c = 0; c < ncell; ++c)
        if (cellPoint[c] >= 0)
            result.cellPoint[c] = index[set.find(cellPoint[c])];
    const int np = static_cast<int>(cc.pieceSite.size());
    result.piecePoints.assign(np, {});
    for (int p = 0; p < np; ++p) {
        std::vector<int> &pts = result.piecePoints[p];
        for (int b : cc.pieceLineComponents[p])
            pts.push_back(result.lineComponentPoint[b]);
        if (pts.empty()) {
            const int c = cc.pieceCell[p];
            if (result.cellPoint[c] >= 0)
                pts.push_back(result.cellPoint[c]);
            else
                for (int b : cc.cellLineComponents[c])
                    pts.push_back(result.lineComponentPoint[b]);
        }
        std::sort(pts.begin(), pts.end());
        pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    }
    return result;
}

} // namespace stratamesh
