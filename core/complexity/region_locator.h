// Which region contains a point: the side of the first surface hit by a ray (Gocad side rule,
// formats.md §0 fact 1: a region listed with +k lies on the side the normal of surface k points
// to). Used for the Voronoi cells that meet no inner surface (thesis §3.3.2: such a cell lies in
// exactly one region).
#pragma once

#include "complexity/triangle_tree.h"
#include "model/model.h"

#include <map>
#include <utility>

namespace stratamesh {

class RegionLocator {
public:
    explicit RegionLocator(const Model &model);
    // The region containing point, -1 outside every region (or when the first hit surface has no
    // region on that side). Thread-safe.
    int regionAt(const Vec3 &point) const;

private:
    const Model &m_model;
    TriangleTree m_tree;
    std::map<std::pair<int, bool>, int> m_regionOfSide; // (surface, positive side) -> region
};

} // namespace stratamesh
