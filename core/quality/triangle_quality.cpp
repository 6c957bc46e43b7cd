#include "quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {

constexpr double kPi = 3.14159265358979323846;

// atan2(|u×v|, u·v) stays accurate for the near-0° and near-180° angles of needle triangles,
// where acos of a normalised dot product loses all its digits.
double angleDeg(const Vec3 &u, const Vec3 &v)
{
    return std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / kPi;
}

} // namespace

TriangleShape triangleShape(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    TriangleShape s;
    const double ab = (b - a).norm();
    const double bc = (c - b).norm();
    const double ca = (a - c).norm();
    s.area = 0.5 * (b - a).cross(c - a).norm();
    s.longestEdge = std::max({ab, bc, ca});
    s.halfPerimeter = 0.5 * (ab + bc + ca);
    s.anglesDeg = {angleDeg(b - a, c - a), angleDeg(c - b, a - b), angleDeg(a - c, b - c)};
    s.minAngleDeg = *std::min_element(s.anglesDeg.begin(), s.anglesDeg.end());
    s.maxAngleDeg = *std::max_element(s.anglesDeg.begin(), s.anglesDeg.end());
    const double denominator = std::sqrt(3.0) * s.longestEdge * s.halfPerimeter;
    s.quality = denominator > 0.0 ? std::clamp(6.0 * s.area / denominator, 0.0, 1.0) : 0.0;
    return s;
}

double triangleArea(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return 0.5 * (b - a).cross(c - a).norm();
}

double triangleQuality(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return triangleShape(a, b, c).quality;
}

double triangleMinAngleDeg(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return triangleShape(a, b, c).minAngleDeg;
}

} // namespace stratamesh
