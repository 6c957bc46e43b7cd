#include "model/bounding_box.h"

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

} // namespace stratamesh
