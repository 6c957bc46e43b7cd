#include "volume/region_winding.h"

#include <Eigen/Geometry>

#include <cmath>

namespace stratamesh {

namespace {

// Signed solid angle of triangle abc seen from p (positive when p is behind its right-hand
// normal), by the Van Oosterom–Strackee formula.
double solidAngle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 u = a - p, v = b - p, w = c - p;
    const double lu = u.norm(), lv = v.norm(), lw = w.norm();
    const double numerator = u.dot(v.cross(w));
    const double denominator = lu * lv * lw + u.dot(v) * lw + v.dot(w) * lu + w.dot(u) * lv;
    return 2.0 * std::atan2(numerator, denominator);
}

} // namespace

double regionWindingNumber(const Model &model, int region, const Vec3 &point)
{
    double sum = 0.0;
    for (const RegionSide &side : model.regions[region].boundaries) {
        const Surface &s = model.surfaces[side.surface];
        // The right-hand normal points into the region on a positive side, so the outward
        // orientation that counts +1 inside is the reversed one.
        double surfaceSum = 0.0;
        for (const Triangle &t : s.triangles)
            surfaceSum += solidAngle(point, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
        sum += side.positive ? -surfaceSum : surfaceSum;
    }
    return sum / (4.0 * M_PI);
}

int locateRegion(const Model &model, const Vec3 &point)
{
    int best = -1;
    double bestGap = 0.5;
    for (int r = 0; r < static_cast<int>(model.regions.size()); ++r) {
        const double gap = std::abs(regionWindingNumber(model, r, point) - 1.0);
        if (gap < bestGap) {
            bestGap = gap;
            best = r;
        }
    }
    return best;
}

} // namespace stratamesh
