// Closest points on the surfaces and lines of the input model, for the vertices the
// post-processing moves or creates: they must stay on the model they remesh (thesis §4.4.5).
// CGAL AABB trees are built per surface on first use.
#pragma once

#include "model/model.h"

#include <map>
#include <memory>
#include <vector>

namespace stratamesh {

class InputProjector {
public:
    explicit InputProjector(const Model &input); // input with topology for lines
    ~InputProjector();
    InputProjector(const InputProjector &) = delete;
    InputProjector &operator=(const InputProjector &) = delete;

    // False when the surface has no non-degenerate triangle (then `x` is returned).
    bool hasSurface(int surface);
    Vec3 onSurface(int surface, const Vec3 &x);
    // The same, starting the search from a point known to be near the answer (a vertex being
    // moved a little): CGAL then skips its own search for a start point.
    Vec3 onSurface(int surface, const Vec3 &x, const Vec3 &near);
    // Closest point on any of the given input lines (x when the list is empty).
    Vec3 onLines(const std::vector<int> &lines, const Vec3 &x) const;

private:
    struct Tree;
    const Model &m_input;
    std::map<int, std::unique_ptr<Tree>> m_trees;
};

} // namespace stratamesh
