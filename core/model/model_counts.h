// Entity counts of a B-Rep model, with and without the box (thesis §3.3.1, Table 3.1: the first
// global measure counts the elements "excluding those defining the volume of interest").
#pragma once

#include "model/model.h"

namespace stratamesh {

struct EntityCounts {
    int regions = 0;
    int surfaces = 0;
    int lines = 0;
    int corners = 0;
    bool operator==(const EntityCounts &o) const
    {
        return regions == o.regions && surfaces == o.surfaces && lines == o.lines
               && corners == o.corners;
    }
};

struct ModelCounts {
    EntityCounts all;
    // The box is the surfaces of type Boundary. A line is a box line when one of its incident
    // surfaces is a box surface; a corner is a box corner when its vertex is a vertex of a box
    // surface. The Universe is not a region, so regions are the same in both counts.
    EntityCounts withoutBox;
};

// Requires topology (recoverTopology); throws InputError otherwise.
ModelCounts countEntities(const Model &model);

// True for the surfaces making the box (volume of interest boundary).
inline bool isBoxSurface(const Surface &s)
{
    return s.type == FeatureType::Boundary;
}

} // namespace stratamesh
