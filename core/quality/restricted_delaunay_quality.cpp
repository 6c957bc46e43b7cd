#include "quality/restricted_delaunay_quality.h"

#include "quality/triangle_quality.h"

#include <algorithm>

namespace stratamesh {

RestrictedDelaunayQuality restrictedDelaunayQuality(const RestrictedDelaunay &rdt)
{
    RestrictedDelaunayQuality q;
    q.triangles = static_cast<int>(rdt.triangles.size());
    if (q.triangles == 0)
        return q;
    double sum = 0;
    int below30 = 0;
    q.minQuality = 1;
    q.minAngleDeg = 180;
    for (const Triangle &t : rdt.triangles) {
        const TriangleShape shape =
            triangleShape(rdt.vertices[t[0]], rdt.vertices[t[1]], rdt.vertices[t[2]]);
        sum += shape.quality;
        q.minQuality = std::min(q.minQuality, shape.quality);
        q.minAngleDeg = std::min(q.minAngleDeg, shape.minAngleDeg);
        below30 += shape.minAngleDeg < 30.0;
    }
    q.meanQuality = sum / q.triangles;
    q.percentAngleBelow30 = 100.0 * below30 / q.triangles;
    return q;
}

} // namespace stratamesh
