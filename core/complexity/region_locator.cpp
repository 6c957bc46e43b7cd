#include "complexity/region_locator.h"

#include <Eigen/Geometry>
#include <numeric>

namespace stratamesh {

namespace {
std::vector<int> allSurfaces(const Model &model)
{
    std::vector<int> all(model.surfaces.size());
    std::iota(all.begin(), all.end(), 0);
    return all;
}
} // namespace

RegionLocator::RegionLocator(const Model &model) : m_model(model), m_tree(model, allSurfaces(model))
{
    for (std::size_t r = 0; r < model.regions.size(); ++r)
        for (const RegionSide &side : model.regions[r].boundaries)
            m_regionOfSide.emplace(std::make_pair(side.surface, side.positive),
                                   static_cast<int>(r));
}

int RegionLocator::regionAt(const Vec3 &point) const
{
    // A direction unlikely to run along mesh edges or axis-aligned box faces.
    const Vec3 direction = Vec3(0.2718, 0.3141, 0.9093).normalized();
    const auto hit = m_tree.firstHit(point, direction);
    if (!hit)
        return -1;
    const Surface &s = m_model.surfaces[hit->triangle.surface];
    const Triangle &t = s.triangles[hit->triangle.triangle];
    const Vec3 normal =
        (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]);
    // The ray leaves the point's region through the surface: the point is on the side the normal
    // points to when the ray goes against the normal.
    const bool positive = normal.dot(direction) < 0.0;
    const auto it = m_regionOfSide.find({hit->triangle.surface, positive});
    return it == m_regionOfSide.end() ? -1 : it->second;
}

} // namespace stratamesh
