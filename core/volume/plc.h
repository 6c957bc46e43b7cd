// The piecewise linear complex given to TetGen (thesis §5.2, comparison meshes of the input and
// of the remeshed model; Si 2015, "TetGen, a Delaunay-based quality tetrahedral mesh generator",
// ACM TOMS 41(2)): every surface triangle as a facet on the model's merged points, and one seed
// point strictly inside each region carrying its attribute.
#pragma once

#include "model/model.h"

#include <string>
#include <vector>

namespace stratamesh {

struct PlcRegion {
    std::string name;
    Vec3 seed = Vec3::Zero();
    int attribute = 0;      // region index + 1 (0 is what TetGen leaves on unassigned tets)
    double clearance = 0.0; // distance from the seed to the nearest surface along the probe ray
};

struct Plc {
    std::vector<Vec3> points;       // the model's global vertices of some triangle, in order
    std::vector<Triangle> facets;   // every surface triangle, on ids into `points`
    std::vector<int> facetMarkers;  // surface index + 1, one per facet
    std::vector<PlcRegion> regions; // in the order of Model::regions
    // TetGen's hole list: the subdomain holding each point is left empty (the zones of a hybrid
    // mesh's own cells, hybrid_mesher.h). buildPlc() leaves it empty.
    std::vector<Vec3> holes;
};

// Builds the PLC; the model's topology is recovered on a copy when it has none. A seed comes from
// a boundary triangle of the region: a ray from its centroid along its normal, on the region's
// side, to the first triangle it hits; the seed is the midpoint, kept only when the region's
// winding number there is 1 (region_winding.h). The largest triangles are tried first and the
// seed with the largest clearance among them wins.
// Throws InputError for an empty model, a triangle whose corners merge into fewer than three
// points, or a region for which no seed is found (unclosed or inconsistent boundary).
Plc buildPlc(const Model &model);

// Finds the seed of one region as buildPlc() does. Throws InputError when there is none.
PlcRegion regionSeed(const Model &model, int region);

} // namespace stratamesh
