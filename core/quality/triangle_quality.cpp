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

double qualityOf(double area, double longestEdge, double halfPerimeter)
{
    const double denominator = std::sqrt(3.0) * longestEdge * halfPerimeter;
    return denominator > 0.0 ? std::clamp(6.0 * area / denominator, 0.0, 1.0) : 0.0;
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
    s.quality = qualityOf(s.area, s.longestEdge, s.halfPerimeter);
    return s;
}

double triangleArea(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return 0.5 * (b - a).cross(c - a).norm();
}

// Without the angles: the remesher's flips and relaxation call it millions of times, and the
// three atan2 of triangleShape were most of its cost. Same operations, so the same bits.
double triangleQuality(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const double ab = (b - a).norm();
    const double bc = (c - b).norm();
    const double ca = (a - c).norm();
    return qualityOf(0.5 * (b - a).cross(c - a).norm(), std::max({ab, bc, ca}),
                     0.5 * (ab + bc + ca));
}

double triangleMinAngleDeg(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return triangleShape(a, b, c).minAngleDeg;
}

} // namespace stratamesh
