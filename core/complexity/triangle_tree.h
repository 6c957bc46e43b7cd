// A bounding-volume tree over the triangles of chosen surfaces of a model (CGAL AABB_tree): the
// candidates of each Voronoi cell, and the rays of point location and thickness measures.
#pragma once

#include "complexity/convex_polyhedron.h"
#include "model/model.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace stratamesh {

struct TriangleRef {
    int surface = -1;
    int triangle = -1;
    bool operator==(const TriangleRef &o) const
    {
        return surface == o.surface && triangle == o.triangle;
    }
    bool operator<(const TriangleRef &o) const
    {
        return surface < o.surface || (surface == o.surface && triangle < o.triangle);
    }
};

struct RayHit {
    TriangleRef triangle;
    double distance = 0.0;
};

class TriangleTree {
public:
    // The triangles of the listed surfaces; degenerate (zero-area) triangles are left out.
    TriangleTree(const Model &model, const std::vector<int> &surfaces);
    ~TriangleTree();
    TriangleTree(const TriangleTree &) = delete;
    TriangleTree &operator=(const TriangleTree &) = delete;

    bool empty() const;
    // Triangles meeting the box, sorted. Thread-safe.
    std::vector<TriangleRef> trianglesInBox(const Box3 &box) const;
    // Nearest triangle hit by the ray from origin along direction, skipping those skip() accepts.
    // Thread-safe.
    std::optional<RayHit> firstHit(const Vec3 &origin, const Vec3 &direction,
                                   const std::function<bool(const TriangleRef &)> &skip = {}) const;

    // Whether a triangle that accept() takes lies within distance radius of point. Thread-safe.
    bool anyWithin(const Vec3 &point, double radius,
                   const std::function<bool(const TriangleRef &)> &accept) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace stratamesh
