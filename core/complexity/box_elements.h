// Which elements make the volume of interest (the box), left out of every complexity measure as
// in the thesis (§3.3.1, §3.5: "the components defining the volume of interest are not taken into
// account"). Same definitions as countEntities() (model/model_counts.h): box surfaces are of type
// Boundary; a box line has a box surface among its incident surfaces; a box corner is a vertex of
// a box surface.
#pragma once

#include "complexity/convex_polyhedron.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct BoxElements {
    std::vector<bool> surface; // per Model::surfaces
    std::vector<bool> line;    // per Model::lines
    std::vector<bool> corner;  // per Model::corners

    // Indices of the elements outside the box.
    std::vector<int> innerSurfaces() const;
    std::vector<int> innerLines() const;
    std::vector<int> innerCorners() const;
};

// Requires topology (Model::hasTopology()); throws InputError otherwise.
BoxElements boxElements(const Model &model);

// The axis-aligned bounding box of all surface vertices.
Box3 modelBounds(const Model &model);

} // namespace stratamesh
