#include "remesh/line_fins.h"

#include "quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <iterator>

namespace stratamesh {

namespace {

bool shareLine(const OutputPoint &a, const OutputPoint &b, const OutputPoint &c)
{
    std::vector<int> ab;
    std::set_intersection(a.lines.begin(), a.lines.end(), b.lines.begin(), b.lines.end(),
                          std::back_inserter(ab));
    for (int l : ab)
        if (std::binary_search(c.lines.begin(), c.lines.end(), l))
            return true;
    return false;
}

} // namespace

int removeLineFins(EditableSoup &soup)
{
    // The middle point must lie nearly on the long edge: an apex angle above this.
    constexpr double minApexDeg = 150.0;
    int removed = 0;
    for (int t = 0; t < soup.triangleCapacity(); ++t) {
        if (!soup.alive(t))
            continue;
        const OutputTriangle fin = soup.triangle(t);
        if (!shareLine(soup.point(fin.v[0]), soup.point(fin.v[1]), soup.point(fin.v[2])))
            continue;
        // The middle point: the one with the widest angle.
        const std::array<double, 3> angles =
            triangleShape(soup.position(fin.v[0]), soup.position(fin.v[1]), soup.position(fin.v[2]))
                .anglesDeg;
        const auto k = std::max_element(angles.begin(), angles.end()) - angles.begin();
        if (angles[k] < minApexDeg)
            continue;
        const int m = fin.v[k], p = fin.v[(k + 1) % 3], q = fin.v[(k + 2) % 3];
        int other = -1, count = 0;
        for (int u : soup.edgeTriangles(p, q))
            if (u != t && soup.triangle(u).surface == fin.surface) {
                other = u;
                ++count;
            }
        if (count != 1)
            continue;
        const OutputTriangle T = soup.triangle(other);
        if (std::find(T.v.begin(), T.v.end(), m) != T.v.end())
            continue;
        // The fin runs p → q; its neighbour runs q → p when both turn the same way.
        if (!hasDirectedEdge(T, q, p))
            continue;
        int x = -1;
        for (int v : T.v)
            if (v != p && v != q)
                x = v;
        const std::array<int, 3> n0{q, m, x}, n1{m, p, x};
        const Vec3 reference = soup.normal(other);
        auto turnsSame = [&](const std::array<int, 3> &v) {
            return (soup.position(v[1]) - soup.position(v[0]))
                       .cross(soup.position(v[2]) - soup.position(v[0]))
                       .dot(reference)
                   > 0.0;
        };
        if (!turnsSame(n0) || !turnsSame(n1) || !soup.edgeTriangles(m, x).empty())
            continue;
        // Only a flip that narrows the widest angle: it ends. Four points of one line holding a
        // surface between them are a fin either way, flipped back and forth forever (a fault
        // piece of an 8-fault network at 2000 sites with its strips kept ran out of memory).
        auto widest = [&](const std::array<int, 3> &v) {
            return triangleShape(soup.position(v[0]), soup.position(v[1]), soup.position(v[2]))
                .maxAngleDeg;
        };
        if (std::max(widest(n0), widest(n1)) >= angles[k])
            continue;
        soup.removeTriangle(t);
        soup.removeTriangle(other);
        soup.addTriangle(n0, fin.surface);
        soup.addTriangle(n1, fin.surface);
        ++removed;
    }
    return removed;
}

} // namespace stratamesh
