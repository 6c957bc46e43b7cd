// The shells of the cells that a model's triangles really bound, against its region sides.
// Around every edge the triangles of all surfaces, sorted by angle, cut space into wedges; the
// two triangle sides facing one wedge see the same piece of space, so they must belong to the
// same region. Linking them across every edge gives the shells a volume mesher floods from a
// seed (TetGen's -A). A shell mixing two regions is a fold along a contact; a region with two
// shells of positive volume is in two pieces, and the smaller is a pocket one seed leaves empty.
// Both pass every combinatorial test (closed, balanced sides) and `tetgen -d`.
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh {

// Two triangles next to each other around an edge whose facing sides belong to two regions.
struct FoldedContact {
    long long edge; // edgeKey of its global vertices
    int surfaceA, surfaceB;
    int regionA, regionB; // index in Model::regions; regions.size() is the Universe
};

// One triangle side facing a pocket.
struct PocketSide {
    int surface;
    int triangle; // local to the surface
    bool positive;
};

// A piece of a region other than its largest.
struct RegionPocket {
    int region;
    double volume;
    std::vector<PocketSide> sides;
    Vec3 centre; // of its triangles
};

struct RegionShells {
    std::vector<FoldedContact> folds;
    std::vector<RegionPocket> pockets;
};

// Requires topology. Sides no region (nor the Universe, when given) claims are left out.
RegionShells analyseRegionShells(const Model &model);

// How many surfaces hold each global vertex of `model` (with topology).
std::vector<int> vertexSurfaceCounts(const Model &model);

// True when flipping the edge a–b (local ids) of surface s changes no shell's sides: every edge
// of its two triangles, before and after, has an end that no other surface holds (`counts` from
// vertexSurfaceCounts), so it stays between two triangles of s, which link the same sides of s
// either way. Only the volumes of the shells on its two sides change, by the tetrahedron of the
// four vertices. False when a–b is not an edge between two triangles of s running it both ways.
bool flipKeepsShells(const Model &model, int s, const std::vector<int> &counts, int a, int b);

} // namespace stratamesh
