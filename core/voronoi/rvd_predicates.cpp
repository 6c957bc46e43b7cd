#include "voronoi/rvd_predicates.h"

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

namespace stratamesh::rvd {
namespace {

std::atomic<long long> g_exactCount{0};

// A double with a running bound on its rounding error: m is the value of the same expression
// on absolute values ("permanent"), k the error count of its longest path. For +,−,× over
// exact doubles, |computed − exact| ≤ γ_k · m with γ_k = k·u / (1 − k·u) (Higham, ch. 3).
struct Fd {
    double v;
    double m;
    int k;
};
inline Fd operator+(const Fd &a, const Fd &b)
{
    return {a.v + b.v, a.m + b.m, std::max(a.k, b.k) + 1};
}
inline Fd operator-(const Fd &a, const Fd &b)
{
    return {a.v - b.v, a.m + b.m, std::max(a.k, b.k) + 1};
}
inline Fd operator*(const Fd &a, const Fd &b)
{
    return {a.v * b.v, a.m * b.m, a.k + b.k + 1};
}

// Sign when the error bound proves it, 0 when in doubt (then exact arithmetic decides).
inline int certainSign(const Fd &x)
{
    constexpr double u = 0x1p-53;
    if (!(x.m > 1e-250) || !(x.m < 1e250))
        return 0; // under/overflow would void the bound
    const double bound = 1.02 * x.k * u * x.m;
    if (x.v > bound)
        return 1;
    if (x.v < -bound)
        return -1;
    return 0;
}

inline int signOf(const CGAL::Mpzf &x)
{
    return static_cast<int>(x.sign());
}

template <class T>
T number(double d);
template <>
inline Fd number<Fd>(double d)
{
    return {d, std::fabs(d), 0};
}
template <>
inline CGAL::Mpzf number<CGAL::Mpzf>(double d)
{
    return CGAL::Mpzf(d);
}

template <class T>
struct P3 {
    T x, y, z;
};
template <class T>
P3<T> point(const Vec3 &v)
{
    return {number<T>(v.x()), number<T>(v.y()), number<T>(v.z())};
}
template <class T>
P3<T> operator-(const P3<T> &a, const P3<T> &b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
P3<T> operator+(const P3<T> &a, const P3<T> &b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
T dot(const P3<T> &a, const P3<T> &b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// |q − pb|² − |q − pa|², written to keep magnitudes small: (pa − pb)·((q − pa) + (q − pb)).
template <class T>
T powerDifference(const P3<T> &q, const P3<T> &pa, const P3<T> &pb)
{
    return dot(pa - pb, (q - pa) + (q - pb));
}

// Symbolic perturbation: the first non-zero coefficient by increasing site index decides.
template <std::size_t N>
int perturbedSign(std::array<std::pair<int, int>, N> indexAndSign)
{
    std::sort(indexAndSign.begin(), indexAndSign.end());
    for (const auto &[index, sign] : indexAndSign)
        if (sign != 0)
            return sign;
    return 1; // all coefficients zero: coincident sites, unreachable for distinct sites
}

// Edge vertex x = (q0, q1) ∩ bisector(i, j), tested against l. With f = π_l − π_i and
// g = π_j − π_i (affine along the segment), f(x) = (g0·f1 − g1·f0) / (g0 − g1).
template <class T>
struct EdgeTerms {
    T f0, f1, g0, g1;
    T numerator() const { return g0 * f1 - g1 * f0; }
    T denominator() const { return g0 - g1; }
};
template <class T>
EdgeTerms<T> edgeTerms(const Vec3 &q0d, const Vec3 &q1d, const Vec3 &pid, const Vec3 &pjd,
                       const Vec3 &pld)
{
    const P3<T> q0 = point<T>(q0d), q1 = point<T>(q1d), pi = point<T>(pid), pj = point<T>(pjd),
                pl = point<T>(pld);
    return {powerDifference(q0, pi, pl), powerDifference(q1, pi, pl), powerDifference(q0, pi, pj),
            powerDifference(q1, pi, pj)};
}

// Face vertex: on the triangle plane x = q0 + u·(q1 − q0) + v·(q2 − q0) (up to a factor 2 on
// u, v), G_m(x) = A_m + u·B_m + v·C_m = π_m − π_i for m ∈ {j, k, l}. x solves G_j = G_k = 0 and
// G_l(x) = det[[A_l,B_l,C_l],[A_j,B_j,C_j],[A_k,B_k,C_k]] / (B_j·C_k − B_k·C_j) by Cramer.
template <class T>
struct FaceTerms {
    T a[3], b[3], c[3]; // index 0: l, 1: j, 2: k
    T minorL() const { return b[1] * c[2] - b[2] * c[1]; }
    T minorJ() const { return b[0] * c[2] - b[2] * c[0]; }
    T minorK() const { return b[0] * c[1] - b[1] * c[0]; }
    T determinant() const { return a[0] * minorL() - a[1] * minorJ() + a[2] * minorK(); }
};
template <class T>
FaceTerms<T> faceTerms(const Vec3 &q0d, const Vec3 &q1d, const Vec3 &q2d, const Vec3 &pid,
                       const Vec3 &pjd, const Vec3 &pkd, const Vec3 &pld)
{
    const P3<T> q0 = point<T>(q0d), q1 = point<T>(q1d), q2 = point<T>(q2d), pi = point<T>(pid);
    const P3<T> e1 = q1 - q0, e2 = q2 - q0;
    const P3<T> ps[3] = {point<T>(pld), point<T>(pjd), point<T>(pkd)};
    FaceTerms<T> t{{number<T>(0), number<T>(0), number<T>(0)},
                   {number<T>(0), number<T>(0), number<T>(0)},
                   {number<T>(0), number<T>(0), number<T>(0)}};
    for (int m = 0; m < 3; ++m) {
        const P3<T> n = pi - ps[m];
        t.a[m] = powerDifference(q0, pi, ps[m]);
        t.b[m] = dot(n, e1);
        t.c[m] = dot(n, e2);
    }
    return t;
}

} // namespace

long long exactPredicateCount()
{
    return g_exactCount.load(std::memory_order_relaxed);
}

int sideOfInputVertex(const Vec3 &q, const Vec3 &pi, int i, const Vec3 &pl, int l)
{
    // Static filter first (the owner walks call this for every point): the same expression in
    // plain doubles, with the bound the Fd filter would give it (6 roundings on its longest
    // path: 1.02·6·u·m ≤ 6.2·u·m for m computed within a few u).
    {
        const Vec3 sa = pi.cwiseAbs() + pl.cwiseAbs();
        const double magnitude = sa.dot(2.0 * q.cwiseAbs() + sa);
        const double value = (pi - pl).dot((q - pi) + (q - pl));
        if (magnitude > 1e-250 && magnitude < 1e250) {
            const double bound = 6.2 * 0x1p-53 * magnitude;
            if (value > bound)
                return 1;
            if (value < -bound)
                return -1;
        }
    }
    const int s = certainSign(powerDifference(point<Fd>(q), point<Fd>(pi), point<Fd>(pl)));
    if (s != 0)
        return s;
    g_exactCount.fetch_add(1, std::memory_order_relaxed);
    using E = CGAL::Mpzf;
    const int e = signOf(powerDifference(point<E>(q), point<E>(pi), point<E>(pl)));
    if (e != 0)
        return e;
    // π_l − π_i = 0 − w_l + w_i: the lower index has the larger weight.
    return i < l ? 1 : -1;
}

int sideOfEdgeVertex(const Vec3 &q0, const Vec3 &q1, const Vec3 &pi, int i, const Vec3 &pj, int j,
                     const Vec3 &pl, int l)
{
    {
        const EdgeTerms<Fd> t = edgeTerms<Fd>(q0, q1, pi, pj, pl);
        const int sn = certainSign(t.numerator());
        const int sd = certainSign(t.denominator());
        if (sn != 0 && sd != 0)
            return sn * sd;
    }
    g_exactCount.fetch_add(1, std::memory_order_relaxed);
    using E = CGAL::Mpzf;
    const EdgeTerms<E> t = edgeTerms<E>(q0, q1, pi, pj, pl);
    const E den = t.denominator();
    const int sd = signOf(den);
    if (sd == 0)
        return 1; // segment parallel to the bisector: no such vertex exists
    int sn = signOf(t.numerator());
    if (sn == 0) {
        // f̃ = f + w_i − w_l, g̃ = g + w_i − w_j: the numerator gains
        // (w_i − w_l)(g0 − g1) + (w_i − w_j)(f1 − f0).
        const E df = t.f1 - t.f0;
        sn = perturbedSign<3>({{{i, signOf(den + df)}, {l, -sd}, {j, -signOf(df)}}});
    }
    return sn * sd;
}

int sideOfFaceVertex(const Vec3 &q0, const Vec3 &q1, const Vec3 &q2, const Vec3 &pi, int i,
                     const Vec3 &pj, int j, const Vec3 &pk, int k, const Vec3 &pl, int l)
{
    {
        const FaceTerms<Fd> t = faceTerms<Fd>(q0, q1, q2, pi, pj, pk, pl);
        const int sn = certainSign(t.determinant());
        const int sd = certainSign(t.minorL());
        if (sn != 0 && sd != 0)
            return sn * sd;
    }
    g_exactCount.fetch_add(1, std::memory_order_relaxed);
    using E = CGAL::Mpzf;
    const FaceTerms<E> t = faceTerms<E>(q0, q1, q2, pi, pj, pk, pl);
    const E ml = t.minorL(), mj = t.minorJ(), mk = t.minorK();
    const int sd = signOf(ml);
    if (sd == 0)
        return 1; // the two bisectors are parallel on this plane: no such vertex exists
    int sn = signOf(t.a[0] * ml - t.a[1] * mj + t.a[2] * mk);
    if (sn == 0) {
        // A_m gains w_i − w_m: the determinant gains
        // w_i (m_l − m_j + m_k) − w_l m_l + w_j m_j − w_k m_k.
        sn = perturbedSign<4>(
            {{{i, signOf(ml - mj + mk)}, {l, -sd}, {j, signOf(mj)}, {k, -signOf(mk)}}});
    }
    return sn * sd;
}

} // namespace stratamesh::rvd
