// A bounding-volume tree over the segments of chosen lines of a model (CGAL AABB_tree): the
// candidate line pieces of each Voronoi cell.
#pragma once

#include "complexity/convex_polyhedron.h"
#include "model/model.h"

#include <memory>
#include <vector>

namespace stratamesh {

// Segment k of a line joins its vertices k and k + 1 (the last one closes a closed line).
struct SegmentRef {
    int line = -1;
    int segment = -1;
    bool operator<(const SegmentRef &o) const
    {
        return line < o.line || (line == o.line && segment < o.segment);
    }
};

int lineSegmentCount(const Line &line);
// End points of segment k, as indices in Model::vertices.
std::pair<int, int> lineSegment(const Line &line, int k);

class SegmentTree {
public:
    SegmentTree(const Model &model, const std::vector<int> &lines);
    ~SegmentTree();
    SegmentTree(const SegmentTree &) = delete;
    SegmentTree &operator=(const SegmentTree &) = delete;

    // Segments meeting the box, sorted. Thread-safe.
    std::vector<SegmentRef> segmentsInBox(const Box3 &box) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace stratamesh
