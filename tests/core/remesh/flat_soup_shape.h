// What the unit tests of the remesher's post-processing steps measure on a soup lying in the
// plane z = 0 with normals +z: small angles, flipped triangles and the area of each surface; and
// a crossing they can plant in it beforehand.
#pragma once

#include "quality/triangle_quality.h"
#include "remesh/editable_soup.h"
#include "remesh/output_mesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace stratamesh::test {

struct FlatSoupShape {
    int small = 0; // triangles under 30°
    int flipped = 0;
    double offPlane = 0.0;      // largest |z| of a vertex of a live triangle
    std::map<int, double> area; // per surface
};

inline FlatSoupShape flatSoupShape(const EditableSoup &soup)
{
    FlatSoupShape s;
    for (int t = 0; t < soup.triangleCapacity(); ++t) {
        if (!soup.alive(t))
            continue;
        const auto &v = soup.triangle(t).v;
        const Vec3 p = soup.position(v[0]), q = soup.position(v[1]), r = soup.position(v[2]);
        s.small += triangleMinAngleDeg(p, q, r) < 30.0 ? 1 : 0;
        const Vec3 n = (q - p).cross(r - p);
        s.flipped += n.z() <= 0.0 ? 1 : 0;
        s.area[soup.triangle(t).surface] += 0.5 * n.norm();
        for (const Vec3 &x : {p, q, r})
            s.offPlane = std::max(s.offPlane, std::abs(x.z()));
    }
    return s;
}

// A small upright triangle of `surface` through the plane z = 0 at (x, y), its corners fixed (each
// a corner of its own): one crossing with the triangle of the soup under (x, y) when that point
// is more than 0.02 from the soup's edges. The needle counts as flipped and off the plane.
inline void addUprightNeedle(OutputMesh &m, double x, double y, int surface)
{
    const Vec3 corners[3] = {{x - 0.02, y - 0.02, -0.1}, {x + 0.02, y + 0.02, -0.1}, {x, y, 0.1}};
    OutputTriangle t;
    t.surface = surface;
    for (int k = 0; k < 3; ++k) {
        OutputPoint p;
        p.position = corners[k];
        p.surfaces = {surface};
        p.corners = {1000 + static_cast<int>(m.points.size())};
        m.points.push_back(p);
        t.v[k] = static_cast<int>(m.points.size()) - 1;
    }
    m.triangles.push_back(t);
}

} // namespace stratamesh::test
