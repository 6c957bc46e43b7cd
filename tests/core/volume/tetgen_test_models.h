// Models built in code for the TetGen tests: a two-region box, and the two defects that make
// TetGen crash or abort (formats.md §4.4-4.5) planted in it.
#pragma once

#include "model/synthetic_models.h"
#include "model/topology.h"

#include <algorithm>

namespace stratamesh::test {

// A 1000 × 600 × 400 box cut by one flat horizon at mid-height: regions layer1 (below), layer2.
inline Model twoRegionBox(double edgeLength = 150.0)
{
    LayeredBoxParams p;
    p.horizons = 1;
    p.edgeLength = edgeLength;
    return recoverTopology(layeredBox(p));
}

// Index of the horizon surface of twoRegionBox().
inline int horizonOf(const Model &m)
{
    for (int s = 0; s < static_cast<int>(m.surfaces.size()); ++s)
        if (m.surfaces[s].type == FeatureType::Horizon)
            return s;
    return -1;
}

// The box with a vertical triangle "piercer" crossing the horizon inside layer1 and layer2.
inline Model selfIntersectingBox()
{
    Model m = twoRegionBox();
    const int h = horizonOf(m);
    double z = 0.0;
    for (const Vec3 &p : m.surfaces[h].vertices)
        z = std::max(z, p.z());
    Surface piercer;
    piercer.name = piercer.featureName = piercer.sourceObject = "piercer";
    piercer.type = FeatureType::Fault;
    piercer.vertices = {{430, 310, z - 70}, {570, 290, z - 70}, {500, 300, z + 80}};
    piercer.triangles = {{0, 1, 2}};
    m.surfaces.push_back(piercer);
    return recoverTopology(m);
}

// The box with one horizon triangle copied into a second surface "copy".
inline Model duplicatedTriangleBox()
{
    Model m = twoRegionBox();
    const Surface &h = m.surfaces[horizonOf(m)];
    Surface copy;
    copy.name = copy.featureName = copy.sourceObject = "copy";
    copy.type = FeatureType::Horizon;
    const Triangle &t = h.triangles[h.triangles.size() / 2];
    copy.vertices = {h.vertices[t[0]], h.vertices[t[1]], h.vertices[t[2]]};
    copy.triangles = {{0, 1, 2}};
    m.surfaces.push_back(copy);
    return recoverTopology(m);
}

} // namespace stratamesh::test
