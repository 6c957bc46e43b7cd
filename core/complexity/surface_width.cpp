#include "complexity/surface_width.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace stratamesh {

namespace {

long long localEdgeKey(int a, int b)
{
    return a < b ? (static_cast<long long>(a) << 32) | static_cast<unsigned>(b)
                 : (static_cast<long long>(b) << 32) | static_cast<unsigned>(a);
}

struct EdgeUse {
    int triangle;
    int edge; // the edge runs from corner `edge` to corner `edge + 1` of the triangle
};

class Walker {
public:
    explicit Walker(const Surface &s) : m_s(s)
    {
        for (std::size_t t = 0; t < s.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                m_edges[key(static_cast<int>(t), k)].push_back({static_cast<int>(t), k});
    }

    long long key(int t, int k) const
    {
        const Triangle &tri = m_s.triangles[t];
        return localEdgeKey(tri[k], tri[(k + 1) % 3]);
    }
    const std::vector<EdgeUse> &uses(int t, int k) const { return m_edges.at(key(t, k)); }
    const Vec3 &corner(int t, int k) const { return m_s.vertices[m_s.triangles[t][k % 3]]; }

    Vec3 normal(int t) const
    {
        return (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
    }

    // Unit vector in triangle t, perpendicular to its edge k, pointing into t.
    Vec3 inward(int t, int k) const
    {
        const Vec3 e = (corner(t, k + 1) - corner(t, k)).normalized();
        Vec3 w = normal(t).normalized().cross(e);
        if (w.dot(corner(t, k + 2) - corner(t, k)) < 0.0)
            w = -w;
        return w;
    }

    // Straight walk from p on edge k of triangle t along d; returns the walked length when it
    // reaches a border, or at least `limit` when it goes further (stopped there).
    double walk(int t, int k, Vec3 p, Vec3 d, double limit) const
    {
        double length = 0.0;
        for (int step = 0; step < 100000; ++step) {
            const Vec3 n = normal(t);
            int exit = -1;
            double best = std::numeric_limits<double>::infinity();
            for (int j = 0; j < 3; ++j) {
                if (j == k)
                    continue;
                const Vec3 a = corner(t, j);
                const Vec3 ab = corner(t, j + 1) - a;
                const double den = d.cross(ab).dot(n);
                if (std::abs(den) < 1e-300)
                    continue;
                const double s = (a - p).cross(ab).dot(n) / den;
                const double u = (a - p).cross(d).dot(n) / den;
                if (s > 0.0 && u >= -1e-9 && u <= 1.0 + 1e-9 && s < best) {
                    best = s;
                    exit = j;
                }
            }
            if (exit < 0)
                return limit; // numerically lost: do not call it thin
            length += best;
            if (length >= limit)
                return length;
            p += best * d;
            const std::vector<EdgeUse> &across = uses(t, exit);
            if (across.size() != 2)
                return length; // a border (or a non-manifold edge)
            const EdgeUse next = across[0].triangle == t ? across[1] : across[0];
            // Unfold d over the shared edge: keep its components along the edge and across it.
            const Vec3 e = (corner(t, exit + 1) - corner(t, exit)).normalized();
            const double along = d.dot(e);
            const double acrossOut = -d.dot(inward(t, exit));
            d = (along * e + acrossOut * inward(next.triangle, next.edge)).normalized();
            t = next.triangle;
            k = next.edge;
        }
        return limit;
    }

private:
    const Surface &m_s;
    std::unordered_map<long long, std::vector<EdgeUse>> m_edges;
};

} // namespace

double surfaceThinShare(const Surface &surface, double h)
{
    const Walker walker(surface);
    double border = 0.0;
    double thin = 0.0;
    for (std::size_t ti = 0; ti < surface.triangles.size(); ++ti) {
        const int t = static_cast<int>(ti);
        if (!(walker.normal(t).norm() > 0.0))
            continue;
        for (int k = 0; k < 3; ++k) {
            if (walker.uses(t, k).size() != 1)
                continue;
            const Vec3 a = walker.corner(t, k);
            const Vec3 b = walker.corner(t, k + 1);
            const double length = (b - a).norm();
            border += length;
            if (walker.walk(t, k, 0.5 * (a + b), walker.inward(t, k), h) < h)
                thin += length;
        }
    }
    return border > 0.0 ? thin / border : 0.0;
}

} // namespace stratamesh
