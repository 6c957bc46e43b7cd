#include "complexity/shape_measure.h"

#include "complexity/element_sizes.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace stratamesh {

double surfaceShapeMeasure(const Surface &surface)
{
    Vec3 areaVector = Vec3::Zero();
    double area = 0.0;
    for (const Triangle &t : surface.triangles) {
        const Vec3 &a = surface.vertices[t[0]];
        const Vec3 n = 0.5 * (surface.vertices[t[1]] - a).cross(surface.vertices[t[2]] - a);
        areaVector += n;
        area += n.norm();
    }
    if (!(area > 0.0))
        return 0.0;
    return std::clamp(1.0 - areaVector.norm() / area, 0.0, 1.0);
}

double lineShapeMeasure(const Model &model, const Line &line)
{
    const std::size_t n = line.vertices.size();
    const double length = lineLength(model, line);
    if (n < 2 || !(length > 0.0))
        return 0.0;
    const int segments = line.closed ? static_cast<int>(n) : static_cast<int>(n) - 1;
    auto end = [&](int k, int which) -> const Vec3 & {
        return model.vertices[line.vertices[(k + which) % n]];
    };
    // Length-weighted mean and covariance of the uniform distribution along the segments.
    Vec3 mean = Vec3::Zero();
    for (int k = 0; k < segments; ++k)
        mean += (end(k, 1) - end(k, 0)).norm() * 0.5 * (end(k, 0) + end(k, 1));
    mean /= length;
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (int k = 0; k < segments; ++k) {
        const Vec3 d = end(k, 1) - end(k, 0);
        const Vec3 m = 0.5 * (end(k, 0) + end(k, 1)) - mean;
        covariance += d.norm() * (m * m.transpose() + d * d.transpose() / 12.0);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    const Vec3 axis = solver.eigenvectors().col(2); // largest eigenvalue last
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (int v : line.vertices) {
        const double x = axis.dot(model.vertices[v] - mean);
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    return std::clamp(1.0 - (hi - lo) / length, 0.0, 1.0);
}

} // namespace stratamesh
