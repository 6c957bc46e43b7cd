#include "remesh/editable_soup.h"

#include "quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace stratamesh {

int cornerIndex(const OutputTriangle &t, int v)
{
    for (int k = 0; k < 3; ++k)
        if (t.v[k] == v)
            return k;
    return -1;
}

bool hasDirectedEdge(const OutputTriangle &t, int a, int b)
{
    const int k = cornerIndex(t, a);
    return k >= 0 && t.v[(k + 1) % 3] == b;
}

namespace {

bool sameVertexSet(std::array<int, 3> a, std::array<int, 3> b)
{
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
}

} // namespace

EditableSoup::EditableSoup(OutputMesh mesh) : m_mesh(std::move(mesh))
{
    m_alive.assign(m_mesh.triangles.size(), true);
    m_vertexTriangles.resize(m_mesh.points.size());
    for (int t = 0; t < static_cast<int>(m_mesh.triangles.size()); ++t)
        for (int v : m_mesh.triangles[t].v)
            m_vertexTriangles[v].push_back(t);
}

OutputMesh EditableSoup::result() const
{
    OutputMesh out;
    out.points = m_mesh.points;
    for (int t = 0; t < static_cast<int>(m_mesh.triangles.size()); ++t)
        if (m_alive[t])
            out.triangles.push_back(m_mesh.triangles[t]);
    out.compact();
    return out;
}

std::vector<int> EditableSoup::edgeTriangles(int a, int b) const
{
    std::vector<int> r;
    for (int t : m_vertexTriangles[a])
        if (cornerIndex(m_mesh.triangles[t], b) >= 0)
            r.push_back(t);
    return r;
}

std::vector<int> EditableSoup::neighbours(int v) const
{
    std::vector<int> r;
    for (int t : m_vertexTriangles[v])
        for (int w : m_mesh.triangles[t].v)
            if (w != v)
                r.push_back(w);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return r;
}

int EditableSoup::edgeTrianglesUpTo3(int a, int b, std::array<int, 3> &out) const
{
    int n = 0;
    for (int t : m_vertexTriangles[a])
        if (cornerIndex(m_mesh.triangles[t], b) >= 0) {
            out[n++] = t;
            if (n == 3)
                break;
        }
    return n;
}

bool EditableSoup::isFeatureEdge(int a, int b) const
{
    std::array<int, 3> tris;
    if (edgeTrianglesUpTo3(a, b, tris) != 2)
        return true;
    const OutputTriangle &t0 = m_mesh.triangles[tris[0]];
    const OutputTriangle &t1 = m_mesh.triangles[tris[1]];
    if (t0.surface != t1.surface)
        return true;
    return hasDirectedEdge(t0, a, b) == hasDirectedEdge(t1, a, b);
}

int EditableSoup::featureEdgeCount(int v) const
{
    int n = 0;
    for (int w : neighbours(v))
        n += isFeatureEdge(v, w) ? 1 : 0;
    return n;
}

VertexClass EditableSoup::vertexClass(int v) const
{
    const std::vector<int> &tris = m_vertexTriangles[v];
    if (tris.empty())
        return VertexClass::Fixed;
    std::vector<int> features;
    for (int w : neighbours(v))
        if (isFeatureEdge(v, w))
            features.push_back(w);
    if (features.empty()) {
        // A single fan: walking across shared edges from one triangle must reach them all
        // (two fans touching at a point are a non-manifold vertex, kept fixed).
        std::vector<int> seen{tris.front()};
        for (std::size_t i = 0; i < seen.size(); ++i) {
            const OutputTriangle &t = m_mesh.triangles[seen[i]];
            for (int w : t.v) {
                if (w == v)
                    continue;
                for (int u : edgeTriangles(v, w))
                    if (std::find(seen.begin(), seen.end(), u) == seen.end())
                        seen.push_back(u);
            }
        }
        return seen.size() == tris.size() ? VertexClass::Interior : VertexClass::Fixed;
    }
    if (features.size() != 2)
        return VertexClass::Fixed;
    auto signature = [&](int w) {
        std::vector<int> s;
        for (int t : edgeTriangles(v, w))
            s.push_back(m_mesh.triangles[t].surface);
        std::sort(s.begin(), s.end());
        return s;
    };
    return signature(features[0]) == signature(features[1]) ? VertexClass::Line
                                                            : VertexClass::Fixed;
}

int EditableSoup::addTriangle(const std::array<int, 3> &v, int surface)
{
    const int t = static_cast<int>(m_mesh.triangles.size());
    m_mesh.triangles.push_back(OutputTriangle{v, surface});
    m_alive.push_back(true);
    for (int w : v)
        m_vertexTriangles[w].push_back(t);
    return t;
}

int EditableSoup::addPoint(const OutputPoint &p)
{
    m_mesh.points.push_back(p);
    m_vertexTriangles.emplace_back();
    return static_cast<int>(m_mesh.points.size()) - 1;
}

void EditableSoup::removeTriangle(int t)
{
    if (!m_alive[t])
        return;
    m_alive[t] = false;
    for (int w : m_mesh.triangles[t].v) {
        auto &list = m_vertexTriangles[w];
        list.erase(std::remove(list.begin(), list.end(), t), list.end());
    }
}

Vec3 EditableSoup::normal(int t) const
{
    const auto &v = m_mesh.triangles[t].v;
    return (position(v[1]) - position(v[0])).cross(position(v[2]) - position(v[0]));
}

double EditableSoup::quality(int t) const
{
    const auto &v = m_mesh.triangles[t].v;
    return triangleQuality(position(v[0]), position(v[1]), position(v[2]));
}

bool EditableSoup::triangleExists(const std::array<int, 3> &v, int ignore1, int ignore2) const
{
    for (int t : m_vertexTriangles[v[0]])
        if (t != ignore1 && t != ignore2 && sameVertexSet(m_mesh.triangles[t].v, v))
            return true;
    return false;
}

// Would moving v to target (and renaming it replaceBy when >= 0) flip a triangle around v, or
// make one a needle worse than both minQuality and what it was?
bool EditableSoup::wouldFlip(int v, const Vec3 &target, const std::vector<int> &skip, int replaceBy,
                             double minQuality) const
{
    for (int t : m_vertexTriangles[v]) {
        if (std::find(skip.begin(), skip.end(), t) != skip.end())
            continue;
        const auto &tv = m_mesh.triangles[t].v;
        std::array<Vec3, 3> p;
        for (int k = 0; k < 3; ++k)
            p[k] = tv[k] == v ? target : position(tv[k]);
        if (replaceBy >= 0 && cornerIndex(m_mesh.triangles[t], replaceBy) >= 0)
            return true; // would become degenerate (two corners equal)
        const Vec3 before = normal(t);
        const Vec3 after = (p[1] - p[0]).cross(p[2] - p[0]);
        if (before.dot(after) <= 0.0)
            return true;
        const double qAfter = triangleQuality(p[0], p[1], p[2]);
        if (qAfter < minQuality && qAfter < quality(t))
            return true;
    }
    return false;
}

bool EditableSoup::collapse(int u, int w, const Vec3 &target, double minQuality, bool checkShape)
{
    if (u == w)
        return false;
    const std::vector<int> shared = edgeTriangles(u, w);
    if (shared.empty())
        return false;
    // Link condition: every common neighbour must close a triangle with the edge.
    const std::vector<int> nu = neighbours(u), nw = neighbours(w);
    std::vector<int> common;
    std::set_intersection(nu.begin(), nu.end(), nw.begin(), nw.end(), std::back_inserter(common));
    for (int x : common) {
        bool found = false;
        for (int t : shared)
            found = found || cornerIndex(m_mesh.triangles[t], x) >= 0;
        if (!found)
            return false;
    }
    if (checkShape
        && (wouldFlip(u, target, shared, w, minQuality)
            || wouldFlip(w, target, shared, -1, minQuality)))
        return false;
    for (int t : m_vertexTriangles[u]) {
        if (std::find(shared.begin(), shared.end(), t) != shared.end())
            continue;
        std::array<int, 3> nv = m_mesh.triangles[t].v;
        nv[cornerIndex(m_mesh.triangles[t], u)] = w;
        if (triangleExists(nv, t, -1))
            return false;
    }
    for (int t : shared)
        removeTriangle(t);
    const std::vector<int> moved = m_vertexTriangles[u];
    for (int t : moved) {
        m_mesh.triangles[t].v[cornerIndex(m_mesh.triangles[t], u)] = w;
        m_vertexTriangles[w].push_back(t);
    }
    m_vertexTriangles[u].clear();
    OutputPoint &pw = m_mesh.points[w];
    const OutputPoint &pu = m_mesh.points[u];
    mergeSortedIds(pw.surfaces, pu.surfaces);
    mergeSortedIds(pw.lines, pu.lines);
    mergeSortedIds(pw.corners, pu.corners);
    pw.position = target;
    return true;
}

bool EditableSoup::flip(int a, int b, bool requireImprovement)
{
    std::array<int, 3> tris;
    if (edgeTrianglesUpTo3(a, b, tris) != 2 || isFeatureEdge(a, b))
        return false;
    int t0 = tris[0], t1 = tris[1];
    if (!hasDirectedEdge(m_mesh.triangles[t0], a, b))
        std::swap(t0, t1);
    const OutputTriangle &T0 = m_mesh.triangles[t0];
    const OutputTriangle &T1 = m_mesh.triangles[t1];
    const int c = T0.v[(cornerIndex(T0, b) + 1) % 3];
    const int d = T1.v[(cornerIndex(T1, a) + 1) % 3];
    std::array<int, 3> existing;
    if (c == d || edgeTrianglesUpTo3(c, d, existing) > 0)
        return false;
    const std::array<int, 3> n0{a, d, c}, n1{d, b, c};
    auto triNormal = [&](const std::array<int, 3> &v) {
        return (position(v[1]) - position(v[0])).cross(position(v[2]) - position(v[0]));
    };
    const Vec3 reference = normal(t0) + normal(t1);
    if (triNormal(n0).dot(reference) <= 0.0 || triNormal(n1).dot(reference) <= 0.0)
        return false;
    auto q = [&](const std::array<int, 3> &v) {
        return triangleQuality(position(v[0]), position(v[1]), position(v[2]));
    };
    if (requireImprovement && std::min(q(n0), q(n1)) <= std::min(quality(t0), quality(t1)))
        return false;
    const int surface = T0.surface;
    removeTriangle(t0);
    removeTriangle(t1);
    addTriangle(n0, surface);
    addTriangle(n1, surface);
    return true;
}

void EditableSoup::splitEdge(int a, int b, int x)
{
    for (int t : edgeTriangles(a, b)) {
        const OutputTriangle T = m_mesh.triangles[t];
        if (cornerIndex(T, x) >= 0)
            continue;
        const int p = hasDirectedEdge(T, a, b) ? a : b;
        const int q = p == a ? b : a;
        const int y = T.v[(cornerIndex(T, q) + 1) % 3];
        removeTriangle(t);
        addTriangle({p, x, y}, T.surface);
        addTriangle({x, q, y}, T.surface);
    }
}

bool EditableSoup::tryMove(int v, const Vec3 &target, double minQuality)
{
    if (wouldFlip(v, target, {}, -1, minQuality))
        return false;
    m_mesh.points[v].position = target;
    return true;
}

} // namespace stratamesh
