#include "remesh/input_projector.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <limits>

namespace stratamesh {

namespace {

using K = CGAL::Simple_cartesian<double>;
using TriangleList = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, TriangleList::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 cg(const Vec3 &v)
{
    return K::Point_3(v.x(), v.y(), v.z());
}

} // namespace

struct InputProjector::Tree {
    TriangleList triangles;
    std::unique_ptr<AabbTree> tree;
};

InputProjector::InputProjector(const Model &input) : m_input(input) {}
InputProjector::~InputProjector() = default;

bool InputProjector::hasSurface(int surface)
{
    if (surface < 0 || surface >= static_cast<int>(m_input.surfaces.size()))
        return false;
    auto it = m_trees.find(surface);
    if (it == m_trees.end()) {
        auto t = std::make_unique<Tree>();
        const Surface &s = m_input.surfaces[surface];
        for (const Triangle &tri : s.triangles) {
            K::Triangle_3 ct(cg(s.vertices[tri[0]]), cg(s.vertices[tri[1]]),
                             cg(s.vertices[tri[2]]));
            if (!ct.is_degenerate())
                t->triangles.push_back(ct);
        }
        if (!t->triangles.empty()) {
            t->tree = std::make_unique<AabbTree>(t->triangles.begin(), t->triangles.end());
            t->tree->accelerate_distance_queries();
        }
        it = m_trees.emplace(surface, std::move(t)).first;
    }
    return it->second->tree != nullptr;
}

Vec3 InputProjector::onSurface(int surface, const Vec3 &x)
{
    if (!hasSurface(surface))
        return x;
    const K::Point_3 q = m_trees[surface]->tree->closest_point(cg(x));
    return Vec3(q.x(), q.y(), q.z());
}

Vec3 InputProjector::onSurface(int surface, const Vec3 &x, const Vec3 &near)
{
    if (!hasSurface(surface))
        return x;
    // The hint itself comes back when no input triangle is closer than it: then it may be off the
    // surface, and only the full search is right.
    const K::Point_3 start = cg(near);
    const K::Point_3 q = m_trees[surface]->tree->closest_point(cg(x), start);
    if (q == start)
        return onSurface(surface, x);
    return Vec3(q.x(), q.y(), q.z());
}

Vec3 InputProjector::onLines(const std::vector<int> &lines, const Vec3 &x) const
{
    double best = std::numeric_limits<double>::max();
    Vec3 result = x;
    for (int l : lines) {
        if (l < 0 || l >= static_cast<int>(m_input.lines.size()))
            continue;
        const Line &line = m_input.lines[l];
        const std::size_t n = line.vertices.size();
        const std::size_t segments = line.closed ? n : (n > 0 ? n - 1 : 0);
        for (std::size_t i = 0; i < segments; ++i) {
            const Vec3 &a = m_input.vertices[line.vertices[i]];
            const Vec3 &b = m_input.vertices[line.vertices[(i + 1) % n]];
            const Vec3 d = b - a;
            const double t =
                d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
            const Vec3 p = a + t * d;
            if ((p - x).squaredNorm() < best) {
                best = (p - x).squaredNorm();
                result = p;
            }
        }
    }
    return result;
}

} // namespace stratamesh
