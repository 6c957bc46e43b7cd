#include "remesh/line_spacing.h"

#include "quality/triangle_quality.h"
#include "remesh/intersection_repair.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace stratamesh {

namespace {

// Collapsing v onto w along their line keeps every surface, line and corner: w is a vertex of
// the same lines, inside them, and each triangle on v–w that goes has its two other edges
// inside its surface, so that no surface piece loses its last triangle there nor gets pinched.
bool keepsTopology(const EditableSoup &soup, int v, int w)
{
    if (soup.vertexClass(w) != VertexClass::Line || soup.point(v).lines != soup.point(w).lines
        || soup.point(v).surfaces != soup.point(w).surfaces || !soup.point(v).corners.empty()
        || !soup.point(w).corners.empty())
        return false;
    for (int t : soup.edgeTriangles(v, w)) {
        const auto &tv = soup.triangle(t).v;
        int x = -1;
        for (int k : tv)
            if (k != v && k != w)
                x = k;
        if (soup.isFeatureEdge(v, x) || soup.isFeatureEdge(w, x))
            return false;
    }
    return true;
}

double worstAround(const EditableSoup &soup, int v)
{
    double worst = std::numeric_limits<double>::max();
    for (int t : soup.vertexTriangles(v))
        worst = std::min(worst, soup.quality(t));
    return worst;
}

// The triangles around v, before and after v goes to w: fewer of them under 30° (the acceptance
// threshold of the remesh), none more. Most collapses in a strip of needles remove two needles
// and widen the others; next to a refined patch they can only close angles.
bool improvesAngles(const EditableSoup &soup, int v, int w)
{
    constexpr double kSmall = 30.0;
    int before = 0, after = 0;
    for (int t : soup.vertexTriangles(v)) {
        const auto &tv = soup.triangle(t).v;
        std::array<Vec3, 3> p, q;
        bool dies = false;
        for (int k = 0; k < 3; ++k) {
            p[k] = soup.position(tv[k]);
            q[k] = tv[k] == v ? soup.position(w) : p[k];
            dies = dies || tv[k] == w;
        }
        before += triangleMinAngleDeg(p[0], p[1], p[2]) < kSmall ? 1 : 0;
        if (!dies)
            after += triangleMinAngleDeg(q[0], q[1], q[2]) < kSmall ? 1 : 0;
    }
    return after < before;
}

// The triangles on the line edge (e, b), in their order about it, from the first one; `moved`
// stands for e's position (v's, or w's once v is collapsed onto it).
std::vector<int> orderAbout(const EditableSoup &soup, const std::vector<int> &triangles, int e,
                            const Vec3 &moved, int b)
{
    const Vec3 d = (soup.position(b) - moved).normalized();
    std::vector<std::pair<double, int>> around;
    Vec3 e1 = Vec3::Zero(), e2 = Vec3::Zero();
    for (int t : triangles) {
        int apex = -1;
        for (int x : soup.triangle(t).v)
            if (x != e && x != b)
                apex = x;
        Vec3 r = soup.position(apex) - moved;
        r -= r.dot(d) * d;
        if (e1.isZero()) {
            e1 = r.normalized();
            e2 = d.cross(e1);
        }
        around.push_back({std::atan2(r.dot(e2), r.dot(e1)), t});
    }
    std::sort(around.begin(), around.end());
    std::vector<int> order;
    for (const auto &entry : around)
        order.push_back(entry.second);
    return order;
}

// Moving the end v of the line edge (v, b) to w keeps the surfaces around it in the same order:
// where contacts meet at low angles, another order folds one surface over another (network of
// one 20° fault at 300 sites: 13 folded contacts in a refinement round without this check).
bool keepsOrderAbout(const EditableSoup &soup, int v, int w, int b)
{
    const std::vector<int> triangles = soup.edgeTriangles(v, b);
    for (int t : triangles)
        if (cornerIndex(soup.triangle(t), w) >= 0)
            return false;
    if (triangles.size() < 3)
        return true;
    std::vector<int> before = orderAbout(soup, triangles, v, soup.position(v), b);
    std::vector<int> after = orderAbout(soup, triangles, v, soup.position(w), b);
    // The same cycle: rotate both to start at the same triangle.
    std::rotate(after.begin(), std::find(after.begin(), after.end(), before.front()), after.end());
    return before == after;
}

// One run of the passes; `banned` vertices stay. Each collapse is listed as (v, w).
std::vector<std::pair<int, int>> collapseLineVertices(EditableSoup &soup,
                                                      const LineSpacingParams &params,
                                                      const std::set<int> &banned)
{
    std::vector<std::pair<int, int>> done;
    for (int pass = 0; pass < params.passes; ++pass) {
        const std::size_t before = done.size();
        for (int v = 0; v < soup.pointCount(); ++v) {
            if (soup.vertexTriangles(v).empty() || soup.vertexClass(v) != VertexClass::Line
                || banned.count(v))
                continue;
            std::vector<int> along;
            double across = 0.0;
            int acrossCount = 0;
            for (int w : soup.neighbours(v)) {
                if (soup.isFeatureEdge(v, w)) {
                    along.push_back(w);
                } else {
                    across += (soup.position(w) - soup.position(v)).norm();
                    ++acrossCount;
                }
            }
            if (along.size() != 2 || acrossCount == 0)
                continue;
            const double d0 = (soup.position(along[0]) - soup.position(v)).norm();
            const double d1 = (soup.position(along[1]) - soup.position(v)).norm();
            if (d0 + d1 >= params.ratio * across / acrossCount)
                continue;
            const int w = d0 <= d1 ? along[0] : along[1];
            const int b = w == along[0] ? along[1] : along[0];
            if (!keepsTopology(soup, v, w) || !improvesAngles(soup, v, w)
                || !keepsOrderAbout(soup, v, w, b))
                continue;
            if (soup.collapse(v, w, soup.position(w), worstAround(soup, v)))
                done.push_back({v, w});
        }
        if (done.size() == before)
            break;
    }
    return done;
}

} // namespace

int spaceLineVertices(EditableSoup &soup, const LineSpacingParams &params)
{
    // The checks are local to the triangles around each vertex; a collapse can still push a
    // triangle through another surface nearby. Then the whole run is made again from the
    // start without the collapses onto the crossing triangles' vertices.
    const EditableSoup start = soup;
    CrossingsAtStart atStart(start);
    std::set<int> banned;
    std::vector<std::pair<int, int>> done;
    for (int attempt = 0; attempt < 4; ++attempt) {
        done = collapseLineVertices(soup, params, banned);
        if (done.empty())
            return 0;
        const std::vector<std::pair<int, int>> pairs = soupIntersections(soup);
        if (!atStart.exceededBy(pairs.size()))
            return static_cast<int>(done.size());
        std::set<int> touched;
        for (const auto &[a, b] : pairs)
            for (int t : {a, b})
                for (int x : soup.triangle(t).v)
                    touched.insert(x);
        const std::size_t bannedBefore = banned.size();
        for (const auto &[v, w] : done)
            if (touched.count(w))
                banned.insert(v);
        soup = start;
        if (banned.size() == bannedBefore)
            break; // the crossings are not the collapses' own
    }
    soup = start;
    return 0;
}

} // namespace stratamesh
