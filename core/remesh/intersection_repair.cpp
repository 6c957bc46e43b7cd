#include "remesh/intersection_repair.h"

#include "common/translate_noop.h"
#include "remesh/mesh_cleanup.h"
#include "remesh/triangle_intersections.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace stratamesh {

namespace {

// Exact test of two soup triangles through a local copy of their (at most six) corners.
bool pairIntersects(const EditableSoup &soup, int t, int u)
{
    std::vector<int> ids;
    std::vector<Vec3> pts;
    auto local = [&](int v) {
        for (std::size_t i = 0; i < ids.size(); ++i)
            if (ids[i] == v)
                return static_cast<int>(i);
        ids.push_back(v);
        pts.push_back(soup.position(v));
        return static_cast<int>(ids.size() - 1);
    };
    Triangle a, b;
    for (int k = 0; k < 3; ++k)
        a[k] = local(soup.triangle(t).v[k]);
    for (int k = 0; k < 3; ++k)
        b[k] = local(soup.triangle(u).v[k]);
    return trianglesIntersect(pts, a, b);
}

struct BBox {
    Vec3 lo, hi;
    bool overlaps(const BBox &o) const
    {
        return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
    }
};

BBox boxOf(const EditableSoup &soup, int t)
{
    BBox b{soup.position(soup.triangle(t).v[0]), soup.position(soup.triangle(t).v[0])};
    for (int k = 1; k < 3; ++k) {
        b.lo = b.lo.cwiseMin(soup.position(soup.triangle(t).v[k]));
        b.hi = b.hi.cwiseMax(soup.position(soup.triangle(t).v[k]));
    }
    return b;
}

// Does any of `tris` intersect another alive triangle? A linear scan: repairs are rare.
bool anyIntersection(const EditableSoup &soup, const std::vector<int> &tris)
{
    for (int t : tris) {
        if (!soup.alive(t))
            continue;
        const BBox bt = boxOf(soup, t);
        for (int u = 0; u < soup.triangleCapacity(); ++u)
            if (u != t && soup.alive(u) && bt.overlaps(boxOf(soup, u))
                && pairIntersects(soup, t, u))
                return true;
    }
    return false;
}

// Flips an edge of triangle `tri` (given by its corners: a refused flip is undone by flipping
// back, which renumbers the triangles).
bool tryFlips(EditableSoup &soup, const std::array<int, 3> &tri)
{
    for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        const std::vector<int> before = soup.edgeTriangles(a, b);
        if (before.size() != 2 || soup.isFeatureEdge(a, b))
            continue;
        std::vector<int> opposite;
        for (int u : before)
            for (int w : soup.triangle(u).v)
                if (w != a && w != b)
                    opposite.push_back(w);
        if (!soup.flip(a, b, false))
            continue;
        if (!anyIntersection(soup, soup.edgeTriangles(opposite[0], opposite[1])))
            return true;
        soup.flip(opposite[0], opposite[1], false); // back to the original pair
    }
    return false;
}

bool tryMoves(EditableSoup &soup, const std::array<int, 3> &tri, double minQuality)
{
    for (int v : tri) {
        const VertexClass c = soup.vertexClass(v);
        if (c == VertexClass::Fixed)
            continue;
        std::vector<int> ring;
        for (int w : soup.neighbours(v))
            if (c == VertexClass::Interior || soup.isFeatureEdge(v, w))
                ring.push_back(w); // a line vertex slides along its line only
        if (ring.empty())
            continue;
        Vec3 average = Vec3::Zero();
        for (int w : ring)
            average += soup.position(w);
        average /= static_cast<double>(ring.size());
        const Vec3 old = soup.position(v);
        for (double f : {1.0, 0.5, 0.25}) {
            if (!soup.tryMove(v, old + f * (average - old), minQuality))
                continue;
            if (!anyIntersection(soup, soup.vertexTriangles(v)))
                return true;
            soup.point(v).position = old;
        }
    }
    return false;
}

// Last resort (thesis §4.4.2: features below the resolution are merged): collapse an edge of
// one of the triangles, the shortest first, when fewer triangles intersect around it after.
bool tryCollapses(EditableSoup &soup, const Model &input, const std::array<int, 3> &a,
                  const std::array<int, 3> &b, SimplificationLedger &ledger)
{
    std::vector<std::pair<double, std::pair<int, int>>> edges;
    for (const auto &tri : {a, b})
        for (int k = 0; k < 3; ++k) {
            const int u = tri[k], w = tri[(k + 1) % 3];
            edges.push_back({(soup.position(u) - soup.position(w)).norm(), {u, w}});
        }
    std::sort(edges.begin(), edges.end());
    for (const auto &[length, edge] : edges) {
        int u = edge.first, w = edge.second;
        const auto rank = [&](int v) { return static_cast<int>(soup.vertexClass(v)); };
        if (rank(u) > rank(w))
            std::swap(u, w);
        const Vec3 target = rank(u) == rank(w) ? Vec3(0.5 * (soup.position(u) + soup.position(w)))
                                               : soup.position(w);
        LedgerRecord r;
        r.kind = LedgerKind::CloseFeatureMerge;
        r.inputs = inputEntitiesOf(soup, input, {u, w});
        r.outputs = {vertexRef(w)};
        r.position = target;
        r.size = length;
        r.sizeMeaning = "distance";
        setNote(r, {QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "points closer than the resolution merged to undo intersecting triangles"),
                    {}});
        const int before = intersectionsAroundVertices(soup, {u, w});
        for (bool checkShape : {true, false}) {
            EditableSoup backup = soup;
            if (soup.collapse(u, w, target, 0.0, checkShape)
                && intersectionsAroundVertices(soup, {w}) < before) {
                ledger.push_back(r);
                return true;
            }
            soup = std::move(backup);
        }
    }
    return false;
}

} // namespace

int intersectionsAroundVertices(const EditableSoup &soup, const std::vector<int> &vertices)
{
    std::vector<int> tris;
    for (int v : vertices)
        tris.insert(tris.end(), soup.vertexTriangles(v).begin(), soup.vertexTriangles(v).end());
    std::sort(tris.begin(), tris.end());
    tris.erase(std::unique(tris.begin(), tris.end()), tris.end());
    int count = 0;
    for (int t : tris) {
        const BBox bt = boxOf(soup, t);
        for (int u = 0; u < soup.triangleCapacity(); ++u) {
            if (u == t || !soup.alive(u)
                || (std::binary_search(tris.begin(), tris.end(), u) && u < t))
                continue;
            if (bt.overlaps(boxOf(soup, u)) && pairIntersects(soup, t, u))
                ++count;
        }
    }
    return count;
}

std::vector<std::pair<int, int>> soupIntersections(const EditableSoup &soup)
{
    std::vector<Vec3> pts(soup.pointCount());
    for (int v = 0; v < soup.pointCount(); ++v)
        pts[v] = soup.position(v);
    std::vector<Triangle> tris;
    std::vector<int> ids;
    for (int t = 0; t < soup.triangleCapacity(); ++t)
        if (soup.alive(t)) {
            tris.push_back(soup.triangle(t).v);
            ids.push_back(t);
        }
    std::vector<std::pair<int, int>> pairs = findIntersectingTriangles(pts, tris);
    for (auto &p : pairs)
        p = {ids[p.first], ids[p.second]};
    return pairs;
}

bool CrossingsAtStart::exceededBy(std::size_t pairs)
{
    if (pairs == 0)
        return false;
    if (!count_)
        count_ = soupIntersections(start_).size();
    return pairs > *count_;
}

IntersectionRepairResult repairIntersections(EditableSoup &soup, const Model &input,
                                             const IntersectionRepairParams &params,
                                             SimplificationLedger &ledger, Progress &progress)
{
    IntersectionRepairResult result;
    progress.tick(0.0, "search");
    std::vector<std::pair<int, int>> pairs = soupIntersections(soup);
    result.found = static_cast<int>(pairs.size());
    // Each round is one search of the whole soup: the rounds share the first half of the bar.
    for (int round = 0; round < params.maxRounds && !pairs.empty(); ++round) {
        progress.tick(0.5 * (round + 1) / (params.maxRounds + 1), "flips and moves");
        for (const auto &[t, u] : pairs) {
            if (!soup.alive(t) || !soup.alive(u) || !pairIntersects(soup, t, u))
                continue;
            const std::array<int, 3> a = soup.triangle(t).v, b = soup.triangle(u).v;
            if (tryFlips(soup, a) || tryFlips(soup, b) || tryMoves(soup, a, params.minQuality))
                continue;
            tryMoves(soup, b, params.minQuality);
        }
        pairs = soupIntersections(soup);
    }
    // Merges go on while they make progress: each one removes at least one intersecting pair.
    for (int round = 0; params.allowMerges && round < 4 * params.maxRounds && !pairs.empty();
         ++round) {
        progress.tick(0.5 + 0.5 * (round + 1) / (4 * params.maxRounds + 1), "merges");
        bool changed = false;
        for (const auto &[t, u] : pairs) {
            if (!soup.alive(t) || !soup.alive(u) || !pairIntersects(soup, t, u))
                continue;
            changed = tryCollapses(soup, input, soup.triangle(t).v, soup.triangle(u).v, ledger)
                      || changed;
        }
        progress.tick(0.5 + 0.5 * (round + 1.5) / (4 * params.maxRounds + 1), "search");
        pairs = soupIntersections(soup);
        if (!changed)
            break;
    }
    result.unresolved = static_cast<int>(pairs.size());
    result.resolved = std::max(0, result.found - result.unresolved);
    for (const auto &[t, u] : pairs) {
        LedgerRecord r;
        r.kind = LedgerKind::IntersectionUnresolved;
        std::vector<int> points(soup.triangle(t).v.begin(), soup.triangle(t).v.end());
        points.insert(points.end(), soup.triangle(u).v.begin(), soup.triangle(u).v.end());
        r.inputs = inputEntitiesOf(soup, input, points);
        for (int v : points)
            addUnique(r.outputs, vertexRef(v));
        Vec3 c = Vec3::Zero();
        for (int v : points)
            c += soup.position(v);
        r.position = c / 6.0;
        r.size = 0.5 * (soup.normal(t).norm() + soup.normal(u).norm()) * 0.5;
        r.sizeMeaning = "area";
        setNote(r,
                {QT_TRANSLATE_NOOP("stratamesh::Core",
                                   "output triangles still intersect after flips and vertex moves"),
                 {}});
        ledger.push_back(r);
    }
    return result;
}

} // namespace stratamesh
