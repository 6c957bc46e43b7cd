#include "complexity/triangle_tree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <iterator>

namespace stratamesh {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using Iterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 toPoint(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}
} // namespace

struct TriangleTree::Impl {
    std::vector<Triangle3> triangles;
    std::vector<TriangleRef> refs;
    Tree tree;
};

TriangleTree::TriangleTree(const Model &model, const std::vector<int> &surfaces) : m(new Impl)
{
    for (int s : surfaces) {
        const Surface &surface = model.surfaces[s];
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const Triangle &tri = surface.triangles[t];
            Triangle3 triangle(toPoint(surface.vertices[tri[0]]), toPoint(surface.vertices[tri[1]]),
                               toPoint(surface.vertices[tri[2]]));
            if (triangle.is_degenerate())
                continue;
            m->triangles.push_back(triangle);
            m->refs.push_back({s, static_cast<int>(t)});
        }
    }
    if (!m->triangles.empty()) {
        m->tree.insert(m->triangles.cbegin(), m->triangles.cend());
        m->tree.build();
    }
}

TriangleTree::~TriangleTree() = default;

bool TriangleTree::empty() const
{
    return m->triangles.empty();
}

std::vector<TriangleRef> TriangleTree::trianglesInBox(const Box3 &box) const
{
    std::vector<TriangleRef> out;
    if (empty() || box.isEmpty())
        return out;
    const CGAL::Bbox_3 query(box.min().x(), box.min().y(), box.min().z(), box.max().x(),
                             box.max().y(), box.max().z());
    std::vector<Iterator> hits;
    m->tree.all_intersected_primitives(query, std::back_inserter(hits));
    out.reserve(hits.size());
    for (Iterator it : hits)
        out.push_back(m->refs[it - m->triangles.cbegin()]);
    std::sort(out.begin(), out.end());
    return out;
}

bool TriangleTree::anyWithin(const Vec3 &point, double radius,
                             const std::function<bool(const TriangleRef &)> &accept) const
{
    if (empty())
        return false;
    const CGAL::Bbox_3 query(point.x() - radius, point.y() - radius, point.z() - radius,
                             point.x() + radius, point.y() + radius, point.z() + radius);
    std::vector<Iterator> hits;
    m->tree.all_intersected_primitives(query, std::back_inserter(hits));
    const Kernel::Point_3 p = toPoint(point);
    for (Iterator it : hits)
        if (accept(m->refs[it - m->triangles.cbegin()])
            && CGAL::squared_distance(p, *it) < radius * radius)
            return true;
    return false;
}

std::optional<RayHit>
TriangleTree::firstHit(const Vec3 &origin, const Vec3 &direction,
                       const std::function<bool(const TriangleRef &)> &skip) const
{
    if (empty())
        return std::nullopt;
    const Kernel::Ray_3 ray(toPoint(origin),
                            Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
    auto skipId = [&](const Iterator &it) {
        return skip && skip(m->refs[it - m->triangles.cbegin()]);
    };
    const auto hit = m->tree.first_intersection(ray, skipId);
    if (!hit)
        return std::nullopt;
    const Kernel::Point_3 *p = boost::get<Kernel::Point_3>(&hit->first);
    RayHit result;
    result.triangle = m->refs[hit->second - m->triangles.cbegin()];
    if (p) {
        result.distance = (Vec3(p->x(), p->y(), p->z()) - origin).norm();
    } else if (const Kernel::Segment_3 *s = boost::get<Kernel::Segment_3>(&hit->first)) {
        // The ray runs inside the triangle's plane: its first point is the nearest one.
        const Vec3 a(s->source().x(), s->source().y(), s->source().z());
        const Vec3 b(s->target().x(), s->target().y(), s->target().z());
        result.distance = std::min((a - origin).norm(), (b - origin).norm());
    }
    return result;
}

} // namespace stratamesh
