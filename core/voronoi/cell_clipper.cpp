#include "voronoi/cell_clipper.h"

#include "voronoi/rvd_predicates.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stratamesh::rvd {
namespace {

constexpr double kUnit = 0x1p-53;

Vec3 absolute(const Vec3 &v)
{
    return v.cwiseAbs();
}

// Power difference |q − pb|² − |q − pa|² and the magnitude bounding its rounding error.
inline double powerDifference(const Vec3 &q, const Vec3 &pa, const Vec3 &pb, double &magnitude)
{
    const Vec3 s = absolute(pa) + absolute(pb);
    magnitude = s.dot(2.0 * absolute(q) + s);
    return (pa - pb).dot((q - pa) + (q - pb));
}

} // namespace

ComputedPoint edgeVertexPoint(const std::vector<Vec3> &points, const std::vector<Vec3> &sites,
                              int a, int b, int s0, int s1)
{
    if (a > b)
        std::swap(a, b);
    if (s0 > s1)
        std::swap(s0, s1);
    const Vec3 &q0 = points[a], &q1 = points[b];
    const Vec3 &ps = sites[s0], &pt = sites[s1];
    double m0 = 0, m1 = 0;
    const double g0 = powerDifference(q0, ps, pt, m0);
    const double g1 = powerDifference(q1, ps, pt, m1);
    const double den = g0 - g1;
    const Vec3 d = q1 - q0;
    const double length = d.norm();
    ComputedPoint r;
    // g0 and g1 have opposite exact signs, so g0 − g1 has no cancellation.
    double dt = 1.0;
    r.t = 0.5;
    if (den != 0) {
        r.t = std::clamp(g0 / den, 0.0, 1.0);
        dt = std::min(1.0, 6.2 * kUnit * (m0 + m1) / std::fabs(den) + 4 * kUnit);
    }
    r.position = q0 + r.t * d;
    const double rounding = 4 * kUnit * (q0.norm() + length);
    r.error = std::min(1.01 * length * dt, length) + rounding;
    return r;
}

ComputedPoint faceVertexPoint(const Vec3 &q0, const Vec3 &q1, const Vec3 &q2,
                              const std::vector<Vec3> &sites, int s0, int s1, int s2, double &u,
                              double &v)
{
    int s[3] = {s0, s1, s2};
    std::sort(s, s + 3);
    const Vec3 &pa = sites[s[0]];
    const Vec3 e1 = q1 - q0, e2 = q2 - q0;
    double A[2], B[2], C[2], eA[2], eB[2], eC[2];
    for (int m = 0; m < 2; ++m) {
        const Vec3 &pm = sites[s[m + 1]];
        const Vec3 n = pa - pm;
        double mag = 0;
        A[m] = powerDifference(q0, pa, pm, mag);
        eA[m] = 6.2 * kUnit * mag;
        const Vec3 sn = absolute(pa) + absolute(pm);
        B[m] = 2 * n.dot(e1);
        C[m] = 2 * n.dot(e2);
        eB[m] = 2 * 5.2 * kUnit * sn.dot(absolute(q1) + absolute(q0));
        eC[m] = 2 * 5.2 * kUnit * sn.dot(absolute(q2) + absolute(q0));
    }
    // Products x·y − z·w with first-order error propagation.
    const auto cross2 = [](double x, double ex, double y, double ey, double z, double ez, double w,
                           double ew, double &err) {
        const double r = x * y - z * w;
        err = std::fabs(x) * ey + ex * std::fabs(y) + ex * ey + std::fabs(z) * ew
              + ez * std::fabs(w) + ez * ew + 3 * kUnit * (std::fabs(x * y) + std::fabs(z * w));
        return r;
    };
    double eD = 0, eNu = 0, eNv = 0;
    const double D = cross2(B[0], eB[0], C[1], eC[1], B[1], eB[1], C[0], eC[0], eD);
    const double Nu = cross2(A[1], eA[1], C[0], eC[0], A[0], eA[0], C[1], eC[1], eNu);
    const double Nv = cross2(B[1], eB[1], A[0], eA[0], B[0], eB[0], A[1], eA[1], eNv);
    const double diameter = std::max({e1.norm(), e2.norm(), (q2 - q1).norm()});
    const double rounding = 6 * kUnit * (q0.norm() + e1.norm() + e2.norm());
    ComputedPoint r;
    double error = diameter;
    if (std::fabs(D) > 2 * eD) {
        u = Nu / D;
        v = Nv / D;
        const double du =
            (eNu + std::fabs(u) * eD) / (std::fabs(D) - eD) + 2 * kUnit * std::fabs(u);
        const double dv =
            (eNv + std::fabs(v) * eD) / (std::fabs(D) - eD) + 2 * kUnit * std::fabs(v);
        error = 1.01 * (e1.norm() * du + e2.norm() * dv);
    } else {
        u = v = 1.0 / 3.0;
    }
    const Vec3 raw = q0 + u * e1 + v * e2;
    // The exact point is inside the triangle: clamping can only bring us within its diameter.
    u = std::max(u, 0.0);
    v = std::max(v, 0.0);
    if (u + v > 1) {
        const double sum = u + v;
        u /= sum;
        v /= sum;
    }
    r.position = q0 + u * e1 + v * e2;
    r.error = std::min(error + (r.position - raw).norm(), diameter) + rounding;
    return r;
}

CellClipper::CellClipper(const RestrictionDomain &domain, const VoronoiNeighbours &delaunay)
    : m_domain(domain), m_delaunay(delaunay)
{
    m_polygon.reserve(16);
    m_next.reserve(16);
    m_visited.reserve(16);
    m_marks.assign(delaunay.siteCount(), 0);
}

namespace {

// The input triangle in the site's frame; r2 and largestError receive the largest |x'|² and
// the largest position error over its corners. Inlined in clipTriangle (once per triangle–site
// pair, its call and a second pass over the corners cost as much as the corners themselves).
inline __attribute__((always_inline)) void siteFrameTriangle(const Triangle &tri,
                                                             const std::vector<Vec3> &points,
                                                             const Vec3 &pi, ClipPolygon &polygon,
                                                             double &r2, double &largestError)
{
    polygon.resize(3);
    ClipVertex *const v = polygon.data();
    r2 = 0;
    largestError = 0;
    for (int c = 0; c < 3; ++c) {
        v[c].position = points[tri[c]] - pi;
        v[c].error =
            2 * kUnit
            * v[c].position.lpNorm<1>(); // one rounded subtraction per coordinate (|·|₂ ≤ |·|₁)
        v[c].u = c == 1 ? 1.0 : 0.0;
        v[c].v = c == 2 ? 1.0 : 0.0;
        v[c].out = inputEdgeSupport(c);
        v[c].norm2 = v[c].position.squaredNorm();
        r2 = std::max(r2, v[c].norm2);
        largestError = std::max(largestError, v[c].error);
    }
}

} // namespace

void CellClipper::wholeTriangle(int t, int site, ClipPolygon &polygon) const
{
    double r2 = 0, largestError = 0;
    siteFrameTriangle(m_domain.triangles[t], m_domain.points, m_delaunay.site(site), polygon, r2,
                      largestError);
}

ClipVertex CellClipper::symbolicCut(int t, int site, int support, int l) const
{
    const Triangle &tri = m_domain.triangles[t];
    const std::vector<Vec3> &pts = m_domain.points;
    const Vec3 &pi = m_delaunay.site(site);
    ClipVertex x;
    ComputedPoint p;
    if (support < 0) {
        const int ca = inputEdgeOf(support), cb = (ca + 1) % 3;
        p = edgeVertexPoint(pts, m_delaunay.sites(), tri[ca], tri[cb], site, l);
        const double tau = tri[ca] < tri[cb] ? p.t : 1.0 - p.t; // from corner ca to corner cb
        double lambda[3] = {0, 0, 0};
        lambda[ca] = 1.0 - tau;
        lambda[cb] = tau;
        x.u = lambda[1];
        x.v = lambda[2];
    } else {
        p = faceVertexPoint(pts[tri[0]], pts[tri[1]], pts[tri[2]], m_delaunay.sites(), site,
                            support, l, x.u, x.v);
    }
    x.position = p.position - pi;
    x.error = p.error + 2 * kUnit * x.position.lpNorm<1>();
    return x;
}

int CellClipper::exactSide(int t, int site, const ClipPolygon &polygon, int k, int l) const
{
    const std::vector<Vec3> &sites = m_delaunay.sites();
    const Vec3 &pi = sites[site], &pl = sites[l];
    const Triangle &tri = m_domain.triangles[t];
    const std::vector<Vec3> &pts = m_domain.points;
    const int n = static_cast<int>(polygon.size());
    const int in = polygon[(k + n - 1) % n].out, out = polygon[k].out;
    if (in < 0 && out < 0)
        return sideOfInputVertex(pts[tri[inputEdgeOf(out)]], pi, site, pl, l);
    if (in < 0 || out < 0) {
        const int e = inputEdgeOf(in < 0 ? in : out);
        const int j = in < 0 ? out : in;
        return sideOfEdgeVertex(pts[tri[e]], pts[tri[(e + 1) % 3]], pi, site, sites[j], j, pl, l);
    }
    return sideOfFaceVertex(pts[tri[0]], pts[tri[1]], pts[tri[2]], pi, site, sites[in], in,
                            sites[out], out, pl, l);
}

void CellClipper::clipTriangle(int t, int site, ClipPolygon &polygon)
{
    const Vec3 &pi = m_delaunay.site(site);
    // Largest |x'| and largest position error over the polygon, and the security radius they
    // give (updated with them: it is compared for every bisector).
    double radius = 0, largestError = 0, reach = 0;
    {
        double r2 = 0;
        siteFrameTriangle(m_domain.triangles[t], m_domain.points, pi, polygon, r2, largestError);
        radius = std::sqrt(r2) * (1 + 4 * kUnit);
        reach = 2.0 * (radius + largestError) * (1.0 + 1e-12);
    }
    // Loaded once here rather than through the members for every bisector.
    const Vec3 *const siteData = m_delaunay.sites().data();
    int *sides = m_sides.data();
    double *values = m_values.data();
    int valueCapacity = static_cast<int>(m_values.size());
    // Clips by bisector(site, l); false once the polygon is empty. Inlined in both loops below
    // (called for every bisector test, its call overhead was a tenth of its cost).
    const auto clip = [&](int l, double dn) __attribute__((always_inline))
    {
        // In the site's frame, π_l − π_i = 2·(h − d·x') with d = p_l − p_i, h = |d|²/2 and
        // dn = |d| rounded. The bound covers the rounding of d, h and the dot product, and the
        // error of x'.
        const Vec3 d = siteData[l] - pi;
        const double h = 0.5 * dn * dn;
        const double bound = 1.01 * dn * largestError + kUnit * (8 * dn * radius + 12 * h);
        const int n = static_cast<int>(polygon.size());
        if (valueCapacity < n) {
            m_sides.resize(2 * n);
            m_values.resize(2 * n);
            sides = m_sides.data();
            values = m_values.data();
            valueCapacity = 2 * n;
        }
        const ClipVertex *const poly = polygon.data();
        int positive = 0;
        for (int k = 0; k < n; ++k) {
            const double value = h - d.dot(poly[k].position);
            values[k] = value;
            sides[k] = value > bound ? 1 : value < -bound ? -1 : exactSide(t, site, polygon, k, l);
            positive += sides[k] > 0;
        }
        if (positive == n)
            return true;
        if (positive == 0) {
            polygon.clear();
            return false;
        }
        // The clipped polygon is built in m_next, measured on the way (same maxima as
        // siteFrameTriangle).
        m_next.clear();
        m_next.reserve(n + 1); // a convex polygon cut by a plane gains at most one vertex
        double r2 = 0, worst = 0;
        for (int k = 0; k < n; ++k) {
            const int k1 = k + 1 == n ? 0 : k + 1;
            const ClipVertex &a = poly[k];
            if (sides[k] > 0) {
                m_next.append() = a;
                r2 = std::max(r2, a.norm2);
                worst = std::max(worst, a.error);
            }
            if (sides[k] == sides[k1])
                continue;
            const ClipVertex &b = poly[k1];
            // The exact crossing lies on the exact edge [a*, b*]; its parameter is known up to
            // the errors of the two values. Unless it is known to 1e-8 (the edge grazes the
            // bisector, or errors have piled up), the point is recomputed from its symbol.
            const double va = values[k], vb = values[k1], gap = std::fabs(va - vb);
            ClipVertex &x = m_next.append();
            if (gap > 2e8 * bound) {
                const double tau = std::clamp(va / (va - vb), 0.0, 1.0);
                const double tauError = 2 * bound / (gap - 2 * bound) + 4 * kUnit;
                const double length = (b.position - a.position).lpNorm<1>(); // bounds |b − a|
                x.position = a.position + tau * (b.position - a.position);
                x.u = a.u + tau * (b.u - a.u);
                x.v = a.v + tau * (b.v - a.v);
                x.error = std::max(a.error, b.error) * (1 + 2 * tauError) + length * tauError
                          + 4 * kUnit * (a.position.lpNorm<1>() + length);
            } else {
                x = symbolicCut(t, site, a.out, l);
            }
            // Leaving the cell, the polygon follows the bisector; entering, it resumes the support
            // that was cut.
            x.out = sides[k] > 0 ? l : a.out;
            x.norm2 = x.position.squaredNorm();
            r2 = std::max(r2, x.norm2);
            worst = std::max(worst, x.error);
        }
        polygon.swap(m_next);
        largestError = worst;
        radius = std::sqrt(r2) * (1 + 4 * kUnit);
        reach = 2.0 * (radius + largestError) * (1.0 + 1e-12);
        return true;
    };
    const int *nb = m_delaunay.neighboursBegin(site);
    const double *dist = m_delaunay.neighbourDistances(site);
    const int count = m_delaunay.neighbourCount(site);
    int q = 0;
    for (; q < count && dist[q] <= reach; ++q)
        if (!clip(nb[q], dist[q]))
            return;
    if (q == count && reach >= m_delaunay.completeRadius(site)) {
        // The list falls short of the security radius: the farther sites, from the kd-tree.
        const double radius0 = reach;
        for (const auto &[dn, l] : sitesBeyondList(site, radius0))
            if (dn <= radius0 && dn <= reach && !clip(l, dn))
                return;
    }
}

void CellClipper::clipSegment(int s, int site, SegmentEnd &first, SegmentEnd &second)
{
    const std::vector<Vec3> &sites = m_delaunay.sites();
    const std::vector<Vec3> &pts = m_domain.points;
    const auto &seg = m_domain.segments[s];
    const Vec3 &pi = sites[site];
    const auto side = [&](const SegmentEnd &e, int l) {
        const Vec3 &pl = sites[l];
        double magnitude = 0;
        const double value = powerDifference(e.position, pi, pl, magnitude);
        const double bound = 6.2 * kUnit * magnitude + 2.02 * (pi - pl).norm() * e.error;
        if (value > bound)
            return 1;
        if (value < -bound)
            return -1;
        if (e.site < 0)
            return sideOfInputVertex(e.t == 0 ? pts[seg[0]] : pts[seg[1]], pi, site, pl, l);
        return sideOfEdgeVertex(pts[seg[0]], pts[seg[1]], pi, site, sites[e.site], e.site, pl, l);
    };
    const auto cut = [&](int l) {
        const ComputedPoint p = edgeVertexPoint(pts, sites, seg[0], seg[1], site, l);
        return SegmentEnd{p.position, p.error, seg[0] < seg[1] ? p.t : 1.0 - p.t, l};
    };
    const int *nb = m_delaunay.neighboursBegin(site);
    const double *dist = m_delaunay.neighbourDistances(site);
    const int count = m_delaunay.neighbourCount(site);
    double limit = 2.0
                   * std::max((first.position - pi).norm() + first.error,
                              (second.position - pi).norm() + second.error)
                   * (1.0 + 1e-12);
    const auto clip = [&](int l) {
        const int a = side(first, l), b = side(second, l);
        if (a < 0)
            throwInconsistent(s);
        if (b > 0)
            return;
        second = cut(l);
        limit = 2.0
                * std::max((first.position - pi).norm() + first.error,
                           (second.position - pi).norm() + second.error)
                * (1.0 + 1e-12);
    };
    int q = 0;
    for (; q < count && dist[q] <= limit; ++q)
        clip(nb[q]);
    if (q == count && limit >= m_delaunay.completeRadius(site)) {
        const double radius0 = limit;
        for (const auto &[dn, l] : sitesBeyondList(site, radius0))
            if (dn <= radius0 && dn <= limit)
                clip(l);
    }
}

const std::vector<std::pair<double, int>> &CellClipper::sitesBeyondList(int site, double radius)
{
    for (const FartherSites &f : m_farther)
        if (f.site == site && f.radius >= radius)
            return f.sites;
    FartherSites &f = m_farther[m_fartherNext];
    m_fartherNext = (m_fartherNext + 1) % static_cast<int>(m_farther.size());
    f.site = site;
    f.radius = radius;
    m_delaunay.sitesBeyondList(site, radius, f.sites);
    return f.sites;
}

void CellClipper::throwInconsistent(int segment) const
{
    throw std::logic_error("restricted Voronoi diagram: inconsistent cells along line segment "
                           + std::to_string(segment));
}

} // namespace stratamesh::rvd
