#include "complexity/convex_polyhedron.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace stratamesh {

namespace {

// Sum over the tetrahedra (ref, face fan triangle) of f(ref, a, b, c, signed volume).
template <class F>
void forEachTetrahedron(const std::vector<Vec3> &vertices, const std::vector<int> &faceStart,
                        const std::vector<int> &faceVertices, const Vec3 &ref, F &&f)
{
    for (std::size_t face = 0; face + 1 < faceStart.size(); ++face) {
        const int begin = faceStart[face];
        const int end = faceStart[face + 1];
        const Vec3 &a = vertices[faceVertices[begin]];
        for (int k = begin + 1; k + 1 < end; ++k) {
            const Vec3 &b = vertices[faceVertices[k]];
            const Vec3 &c = vertices[faceVertices[k + 1]];
            const double volume = (a - ref).dot((b - ref).cross(c - ref)) / 6.0;
            f(a, b, c, volume);
        }
    }
}

} // namespace

ConvexPolyhedron ConvexPolyhedron::box(const Box3 &box)
{
    ConvexPolyhedron p;
    const Vec3 lo = box.min();
    const Vec3 hi = box.max();
    for (int k = 0; k < 8; ++k)
        p.m_vertices.emplace_back((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                  (k & 4) ? hi.z() : lo.z());
    // Vertex k has bit 0 = x, bit 1 = y, bit 2 = z; loops are counter-clockwise from outside.
    const int loops[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (int axis = 0; axis < 3; ++axis) {
        for (int upper = 0; upper < 2; ++upper) {
            const int f = 2 * axis + upper;
            p.m_faceVertices.insert(p.m_faceVertices.end(), loops[f], loops[f] + 4);
            p.m_faceStart.push_back(static_cast<int>(p.m_faceVertices.size()));
            HalfSpace h;
            h.normal = Vec3::Zero();
            h.normal[axis] = upper ? 1.0 : -1.0;
            h.offset = upper ? hi[axis] : -lo[axis];
            h.tag = boxSideTag(axis, upper != 0);
            p.m_planes.push_back(h);
        }
    }
    // Relative tolerance: coordinates of real models are ~1e4 m, doubles carry ~1e-16 relative.
    p.m_eps =
        1e-10 * std::max((hi - lo).norm(), hi.cwiseAbs().maxCoeff() + lo.cwiseAbs().maxCoeff());
    return p;
}

bool ConvexPolyhedron::clip(const HalfSpace &halfSpace)
{
    thread_local ClipWorkspace workspace;
    return clip(halfSpace, workspace);
}

bool ConvexPolyhedron::clip(const HalfSpace &halfSpace, ClipWorkspace &s)
{
    if (empty())
        return false;
    const double length = halfSpace.normal.norm();
    if (!(length > 0.0))
        return false;
    HalfSpace plane = halfSpace;
    plane.normal /= length;
    plane.offset /= length;

    const int nv = static_cast<int>(m_vertices.size());
    s.side.assign(nv, 0);
    s.dist.resize(nv);
    bool anyOut = false;
    bool anyIn = false;
    for (int v = 0; v < nv; ++v) {
        const double d = plane.normal.dot(m_vertices[v]) - plane.offset;
        s.dist[v] = d;
        s.side[v] = d > m_eps ? 1 : (d < -m_eps ? -1 : 0);
        anyOut |= s.side[v] > 0;
        anyIn |= s.side[v] < 0;
    }
    if (!anyOut)
        return false;
    if (!anyIn) {
        *this = ConvexPolyhedron{};
        return true;
    }

    s.edgeVertex.clear();
    s.faceStart.assign(1, 0);
    s.faceVertices.clear();
    s.planes.clear();
    s.capNext.assign(nv, -1);
    auto onPlane = [&](int v) { return v >= nv || s.side[v] == 0; };
    auto edgeVertex = [&](int a, int b) {
        if (a > b)
            std::swap(a, b);
        for (const auto &e : s.edgeVertex)
            if (e[0] == a && e[1] == b)
                return e[2];
        const double t = s.dist[a] / (s.dist[a] - s.dist[b]);
        const int id = static_cast<int>(m_vertices.size());
        m_vertices.push_back(m_vertices[a] + t * (m_vertices[b] - m_vertices[a]));
        s.capNext.push_back(-1);
        s.edgeVertex.push_back({a, b, id});
        return id;
    };

    for (int f = 0; f < faceCount(); ++f) {
        const int begin = m_faceStart[f];
        const int size = faceSize(f);
        s.out.clear();
        for (int i = 0; i < size; ++i) {
            const int a = m_faceVertices[begin + i];
            const int b = m_faceVertices[begin + (i + 1) % size];
            if (s.side[a] <= 0)
                s.out.push_back(a);
            if (s.side[a] * s.side[b] < 0)
                s.out.push_back(edgeVertex(a, b));
        }
        if (s.out.size() < 3)
            continue;
        s.faceVertices.insert(s.faceVertices.end(), s.out.begin(), s.out.end());
        s.faceStart.push_back(static_cast<int>(s.faceVertices.size()));
        s.planes.push_back(m_planes[f]);
        // The cap runs along the cut edges of the kept faces in the opposite direction.
        const int k = static_cast<int>(s.out.size());
        for (int i = 0; i < k; ++i) {
            const int p = s.out[i];
            const int q = s.out[(i + 1) % k];
            if (onPlane(p) && onPlane(q))
                s.capNext[q] = p;
        }
    }

    s.capVertices.clear();
    for (int v = 0; v < static_cast<int>(s.capNext.size()); ++v)
        if (s.capNext[v] >= 0)
            s.capVertices.push_back(v);

    m_faceStart.swap(s.faceStart);
    m_faceVertices.swap(s.faceVertices);
    m_planes.swap(s.planes);
    plane.tag = halfSpace.tag;
    addCapFace(plane, s.capNext, s.capVertices);
    compact(s.remap);
    if (m_planes.size() < 4)
        *this = ConvexPolyhedron{};
    return true;
}

void ConvexPolyhedron::addCapFace(const HalfSpace &plane, const std::vector<int> &capNext,
                                  const std::vector<int> &capVertices)
{
    if (capVertices.size() < 3)
        return;
    std::vector<int> loop;
    loop.reserve(capVertices.size());
    int v = capVertices.front();
    while (static_cast<int>(loop.size()) <= static_cast<int>(capVertices.size())) {
        loop.push_back(v);
        v = capNext[v];
        if (v < 0 || v == loop.front())
            break;
    }
    if (v != loop.front() || loop.size() != capVertices.size()) {
        // Tolerance made the cut edges inconsistent: order the cut points by angle instead,
        // counter-clockwise seen from the removed side (the outside of the cap).
        loop = capVertices;
        Vec3 center = Vec3::Zero();
        for (int id : loop)
            center += m_vertices[id];
        center /= static_cast<double>(loop.size());
        Vec3 u = plane.normal.unitOrthogonal();
        Vec3 w = plane.normal.cross(u);
        std::vector<double> angle(m_vertices.size(), 0.0);
        for (int id : loop) {
            const Vec3 d = m_vertices[id] - center;
            angle[id] = std::atan2(d.dot(w), d.dot(u));
        }
        std::sort(loop.begin(), loop.end(), [&](int a, int b) { return angle[a] < angle[b]; });
    }
    m_faceVertices.insert(m_faceVertices.end(), loop.begin(), loop.end());
    m_faceStart.push_back(static_cast<int>(m_faceVertices.size()));
    m_planes.push_back(plane);
}

void ConvexPolyhedron::compact(std::vector<int> &remap)
{
    remap.assign(m_vertices.size(), -1);
    for (int v : m_faceVertices)
        remap[v] = 0;
    int next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == 0) {
            remap[v] = next;
            m_vertices[next++] = m_vertices[v];
        }
    }
    m_vertices.resize(next);
    for (int &v : m_faceVertices)
        v = remap[v];
}

double ConvexPolyhedron::volume() const
{
    if (empty())
        return 0.0;
    double total = 0.0;
    forEachTetrahedron(m_vertices, m_faceStart, m_faceVertices, m_vertices.front(),
                       [&](const Vec3 &, const Vec3 &, const Vec3 &, double v) { total += v; });
    return total;
}

Vec3 ConvexPolyhedron::centroid() const
{
    if (empty())
        return Vec3::Zero();
    const Vec3 ref = m_vertices.front();
    double total = 0.0;
    Vec3 moment = Vec3::Zero();
    forEachTetrahedron(m_vertices, m_faceStart, m_faceVertices, ref,
                       [&](const Vec3 &a, const Vec3 &b, const Vec3 &c, double v) {
                           total += v;
                           moment += v * (ref + a + b + c) / 4.0;
                       });
    if (!(total > 0.0)) {
        Vec3 mean = Vec3::Zero();
        for (const Vec3 &p : m_vertices)
            mean += p;
        return mean / static_cast<double>(m_vertices.size());
    }
    return moment / total;
}

double ConvexPolyhedron::secondMoment(const Vec3 &point) const
{
    if (empty())
        return 0.0;
    // ∫_T |x|² = V/20 (Σ|v_i|² + |Σ v_i|²) over a tetrahedron with vertices v_i relative to point.
    double total = 0.0;
    const Vec3 ref = m_vertices.front();
    const Vec3 r = ref - point;
    forEachTetrahedron(m_vertices, m_faceStart, m_faceVertices, ref,
                       [&](const Vec3 &a0, const Vec3 &b0, const Vec3 &c0, double v) {
                           const Vec3 a = a0 - point;
                           const Vec3 b = b0 - point;
                           const Vec3 c = c0 - point;
                           const Vec3 sum = r + a + b + c;
                           total += v / 20.0
                                    * (r.squaredNorm() + a.squaredNorm() + b.squaredNorm()
                                       + c.squaredNorm() + sum.squaredNorm());
                       });
    return total;
}

Box3 ConvexPolyhedron::bounds() const
{
    Box3 b;
    for (const Vec3 &p : m_vertices)
        b.extend(p);
    return b;
}

double ConvexPolyhedron::maxSquaredDistance(const Vec3 &point) const
{
    double r2 = 0.0;
    for (const Vec3 &p : m_vertices)
        r2 = std::max(r2, (p - point).squaredNorm());
    return r2;
}

bool ConvexPolyhedron::contains(const Vec3 &point) const
{
    if (empty())
        return false;
    for (const HalfSpace &h : m_planes)
        if (h.normal.dot(point) - h.offset > m_eps * h.normal.norm())
            return false;
    return true;
}

} // namespace stratamesh
