#include "model/bounding_box.h"

#include <limits>

namespace stratamesh {

double boundingBoxDiagonal(const std::vector<Vec3> &points)
{
    if (points.empty())
        return 0.0;
    Vec3 lo = points.front(), hi = points.front();
    for (const Vec3 &p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

double boundingBoxDiagonal(const Model &model)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = -lo;
    bool any = false;
    for (const Surface &s : model.surfaces)
        for (const Vec3 &v : s.vertices) {
            lo = lo.cwiseMin(v);
            hi = hi.cwiseMax(v);
            any = true;
        }
    return any ? (hi - lo).norm() : 0.0;
}

} // namespace stratamesh
