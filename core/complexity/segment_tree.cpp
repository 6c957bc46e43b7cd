#include "complexity/segment_tree.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <iterator>

namespace stratamesh {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Segment3 = Kernel::Segment_3;
using Iterator = std::vector<Segment3>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}
} // namespace

int lineSegmentCount(const Line &line)
{
    const int n = static_cast<int>(line.vertices.size());
    if (n < 2)
        return 0;
    return line.closed ? n : n - 1;
}

std::pair<int, int> lineSegment(const Line &line, int k)
{
    const int n = static_cast<int>(line.vertices.size());
    return {line.vertices[k], line.vertices[(k + 1) % n]};
}

struct SegmentTree::Impl {
    std::vector<Segment3> segments;
    std::vector<SegmentRef> refs;
    Tree tree;
};

SegmentTree::SegmentTree(const Model &model, const std::vector<int> &lines) : m(new Impl)
{
    for (int l : lines) {
        const Line &line = model.lines[l];
        for (int k = 0; k < lineSegmentCount(line); ++k) {
            const auto [a, b] = lineSegment(line, k);
            Segment3 segment(point(model.vertices[a]), point(model.vertices[b]));
            if (segment.is_degenerate())
                continue;
            m->segments.push_back(segment);
            m->refs.push_back({l, k});
        }
    }
    if (!m->segments.empty()) {
        m->tree.insert(m->segments.cbegin(), m->segments.cend());
        m->tree.build();
    }
}

SegmentTree::~SegmentTree() = default;

std::vector<SegmentRef> SegmentTree::segmentsInBox(const Box3 &box) const
{
    std::vector<SegmentRef> out;
    if (m->segments.empty() || box.isEmpty())
        return out;
    const CGAL::Bbox_3 query(box.min().x(), box.min().y(), box.min().z(), box.max().x(),
                             box.max().y(), box.max().z());
    std::vector<Iterator> hits;
    m->tree.all_intersected_primitives(query, std::back_inserter(hits));
    out.reserve(hits.size());
    for (Iterator it : hits)
        out.push_back(m->refs[it - m->segments.cbegin()]);
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace stratamesh
