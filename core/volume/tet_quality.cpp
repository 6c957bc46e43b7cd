#include "volume/tet_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace stratamesh {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Interior angle at edge pq between the half-planes through r and through s. atan2 keeps the
// precision of slivers' tiny angles, which acos of a dot product loses.
double dihedral(const Vec3 &p, const Vec3 &q, const Vec3 &r, const Vec3 &s)
{
    const Vec3 e = q - p;
    const Vec3 n1 = e.cross(r - p), n2 = e.cross(s - p);
    return std::atan2(n1.cross(n2).norm(), n1.dot(n2));
}

} // namespace

std::array<double, 6> dihedralAnglesDeg(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    constexpr double deg = 180.0 / M_PI;
    return {dihedral(a, b, c, d) * deg, dihedral(a, c, b, d) * deg, dihedral(a, d, b, c) * deg,
            dihedral(b, c, a, d) * deg, dihedral(b, d, a, c) * deg, dihedral(c, d, a, b) * deg};
}

TetQuality tetQuality(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    TetQuality q;
    const Vec3 ab = b - a, ac = c - a, ad = d - a;
    const double det = ab.dot(ac.cross(ad));
    q.volume = det / 6.0;

    const std::array<double, 6> angles = dihedralAnglesDeg(a, b, c, d);
    const auto [lo, hi] = std::minmax_element(angles.begin(), angles.end());
    q.minDihedralDeg = *lo;
    q.maxDihedralDeg = *hi;

    // Twice the face areas.
    const double faces = ab.cross(ac).norm() + ab.cross(ad).norm() + ac.cross(ad).norm()
                         + (c - b).cross(d - b).norm();
    if (det == 0.0) {
        q.radiusRatio = q.aspectRatio = kInf;
        return q;
    }
    // R = |ab²(ac×ad) + ac²(ad×ab) + ad²(ab×ac)| / (2|det|), r = 3|V| / S = |det| / faces.
    const Vec3 circum = ab.squaredNorm() * ac.cross(ad) + ac.squaredNorm() * ad.cross(ab)
                        + ad.squaredNorm() * ab.cross(ac);
    q.radiusRatio = circum.norm() * faces / (6.0 * det * det);
    const double longest =
        std::sqrt(std::max({ab.squaredNorm(), ac.squaredNorm(), ad.squaredNorm(),
                            (c - b).squaredNorm(), (d - b).squaredNorm(), (d - c).squaredNorm()}));
    // Longest edge over the inradius, normalised by the regular tet's 2√6.
    q.aspectRatio = std::sqrt(6.0) / 12.0 * longest * faces / std::abs(det);
    return q;
}

std::vector<TetQuality> tetQualities(const VolumeMesh &mesh)
{
    std::vector<TetQuality> result(mesh.cells.size());
    for (std::size_t i = 0; i < mesh.cells.size(); ++i) {
        const Cell &c = mesh.cells[i];
        if (c.type == CellType::Tet)
            result[i] = tetQuality(mesh.points[c.nodes[0]], mesh.points[c.nodes[1]],
                                   mesh.points[c.nodes[2]], mesh.points[c.nodes[3]]);
    }
    return result;
}

VolumeQualityStatistics volumeQuality(const VolumeMesh &mesh, Progress &progress)
{
    VolumeQualityStatistics s;
    std::vector<char> used(mesh.points.size(), 0);
    double sumRadius = 0.0, sumAspect = 0.0;
    s.minDihedralDeg = kInf;
    s.minVolume = kInf;
    for (std::size_t i = 0; i < mesh.cells.size(); ++i) {
        if (i % 65536 == 0)
            progress.tick(static_cast<double>(i) / mesh.cells.size(), "tet quality");
        const Cell &c = mesh.cells[i];
        if (c.type != CellType::Tet)
            continue;
        for (int k = 0; k < 4; ++k)
            used[c.nodes[k]] = 1;
        const TetQuality q = tetQuality(mesh.points[c.nodes[0]], mesh.points[c.nodes[1]],
                                        mesh.points[c.nodes[2]], mesh.points[c.nodes[3]]);
        ++s.tets;
        s.slivers += q.minDihedralDeg < kSliverDihedralDeg ? 1 : 0;
        s.minDihedralDeg = std::min(s.minDihedralDeg, q.minDihedralDeg);
        s.maxDihedralDeg = std::max(s.maxDihedralDeg, q.maxDihedralDeg);
        s.minVolume = std::min(s.minVolume, q.volume);
        s.totalVolume += q.volume;
        s.minDihedral.add(q.minDihedralDeg);
        s.maxDihedral.add(q.maxDihedralDeg);
        s.inverseRadiusRatio.add(std::isfinite(q.radiusRatio) ? 1.0 / q.radiusRatio : 0.0);
        if (!std::isfinite(q.radiusRatio) || !std::isfinite(q.aspectRatio)) {
            ++s.flat;
            continue;
        }
        sumRadius += q.radiusRatio;
        sumAspect += q.aspectRatio;
        s.maxRadiusRatio = std::max(s.maxRadiusRatio, q.radiusRatio);
        s.maxAspectRatio = std::max(s.maxAspectRatio, q.aspectRatio);
    }
    if (s.tets == 0) {
        s.minDihedralDeg = s.minVolume = 0.0;
        return s;
    }
    const std::size_t shaped = s.tets - s.flat;
    s.meanRadiusRatio = shaped > 0 ? sumRadius / shaped : 0.0;
    s.meanAspectRatio = shaped > 0 ? sumAspect / shaped : 0.0;
    s.points = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
    return s;
}

} // namespace stratamesh
