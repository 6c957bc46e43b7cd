#include "complexity/convex_clip.h"

#include <algorithm>

namespace stratamesh {

namespace {

// Signed distance beyond the plane pushed out by the tolerance: <= 0 means kept.
double excess(const HalfSpace &h, const Vec3 &p, double eps)
{
    return h.normal.dot(p) - h.offset - eps * h.normal.norm();
}

} // namespace

bool segmentMeetsCell(const Vec3 &a, const Vec3 &b, const ConvexPolyhedron &cell)
{
    if (cell.empty())
        return false;
    double lo = 0.0;
    double hi = 1.0;
    const double eps = cell.tolerance();
    for (const HalfSpace &h : cell.planes()) {
        const double da = excess(h, a, eps);
        const double db = excess(h, b, eps);
        if (da > 0.0 && db > 0.0)
            return false;
        if (da > 0.0)
            lo = std::max(lo, da / (da - db));
        else if (db > 0.0)
            hi = std::min(hi, da / (da - db));
        if (lo > hi)
            return false;
    }
    return true;
}

std::vector<Vec3> clipPolygonToCell(std::vector<Vec3> polygon, const ConvexPolyhedron &cell)
{
    if (cell.empty())
        return {};
    const double eps = cell.tolerance();
    std::vector<Vec3> next;
    std::vector<double> d;
    for (const HalfSpace &h : cell.planes()) {
        const std::size_t n = polygon.size();
        if (n == 0)
            break;
        d.resize(n);
        bool anyOut = false;
        for (std::size_t i = 0; i < n; ++i) {
            d[i] = excess(h, polygon[i], eps);
            anyOut |= d[i] > 0.0;
        }
        if (!anyOut)
            continue;
        next.clear();
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            if (d[i] <= 0.0)
                next.push_back(polygon[i]);
            if ((d[i] < 0.0 && d[j] > 0.0) || (d[i] > 0.0 && d[j] < 0.0)) {
                const double t = d[i] / (d[i] - d[j]);
                next.push_back(polygon[i] + t * (polygon[j] - polygon[i]));
            }
        }
        polygon.swap(next);
    }
    return polygon;
}

bool triangleMeetsCell(const Vec3 &a, const Vec3 &b, const Vec3 &c, const ConvexPolyhedron &cell)
{
    if (cell.contains(a) || cell.contains(b) || cell.contains(c))
        return true;
    return !clipPolygonToCell({a, b, c}, cell).empty();
}

} // namespace stratamesh
