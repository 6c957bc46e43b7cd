#include "model/shared_edge_overlap.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Geometry>

namespace stratamesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point toPoint(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

// Overlap needs normals e×(a−u) and e×(b−u) pointing the same way. Clearly opposite normals of
// two clearly non-degenerate triangles settle it in doubles: the rounding of the dot product is
// below 1e-14 of |e|²|a−u||b−u|, the margin asked is 1e-12 of it. Adjacent coplanar triangles
// (planar box faces, flat horizons) are most pairs, and the exact predicates would go to
// multiprecision for every one of them.
bool clearlyUnfolded(const Vec3 &u, const Vec3 &v, const Vec3 &a, const Vec3 &b)
{
    const Vec3 e = v - u, da = a - u, db = b - u;
    const Vec3 na = e.cross(da), nb = e.cross(db);
    const double scaleA = e.norm() * da.norm(), scaleB = e.norm() * db.norm();
    const double lengthA = na.norm(), lengthB = nb.norm();
    constexpr double kNonDegenerate = 1e-6;
    return lengthA > kNonDegenerate * scaleA && lengthB > kNonDegenerate * scaleB
           && na.dot(nb) < -0.5 * lengthA * lengthB;
}

} // namespace

bool sharedEdgeTrianglesOverlap(const Vec3 &u, const Vec3 &v, const Vec3 &a, const Vec3 &b)
{
    if (clearlyUnfolded(u, v, a, b))
        return false;
    const Point pu = toPoint(u), pv = toPoint(v), pa = toPoint(a), pb = toPoint(b);
    if (CGAL::orientation(pu, pv, pa, pb) != CGAL::COPLANAR)
        return false;
    return CGAL::coplanar_orientation(pu, pv, pa, pb) == CGAL::POSITIVE;
}

} // namespace stratamesh
