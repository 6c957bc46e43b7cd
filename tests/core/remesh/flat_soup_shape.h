// What the unit tests of the remesher's post-processing steps measure on a soup lying in the
// plane z = 0 with normals +z: small angles, flipped triangles and the area of each surface.
#pragma once

#include "quality/triangle_quality.h"
#include "remesh/editable_soup.h"

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

} // namespace stratamesh::test
