#include "complexity/region_thickness.h"

#include "complexity/triangle_tree.h"

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <numeric>
#include <utility>

namespace stratamesh {

namespace {

struct Areas {
    double thin = 0.0;
    double all = 0.0;
};

Areas sideAreas(const Model &model, const TriangleTree &tree, const RegionSide &side,
                const std::vector<bool> &bounds, double h)
{
    const Surface &s = model.surfaces[side.surface];
    // Another boundary surface of the same region.
    const auto other = [&](const TriangleRef &ref) {
        return ref.surface != side.surface && bounds[ref.surface];
    };
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, s.triangles.size(), 256), Areas{},
        [&](const tbb::blocked_range<std::size_t> &r, Areas sum) {
            for (std::size_t t = r.begin(); t != r.end(); ++t) {
                const Triangle &tri = s.triangles[t];
                const Vec3 &a = s.vertices[tri[0]];
                const Vec3 &b = s.vertices[tri[1]];
                const Vec3 &c = s.vertices[tri[2]];
                const double area = 0.5 * (b - a).cross(c - a).norm();
                if (!(area > 0.0))
                    continue;
                sum.all += area;
                if (tree.anyWithin((a + b + c) / 3.0, h, other))
                    sum.thin += area;
            }
            return sum;
        },
        [](Areas x, const Areas &y) {
            x.thin += y.thin;
            x.all += y.all;
            return x;
        });
}

} // namespace

std::vector<std::vector<SideThinArea>> regionSideThinAreas(const Model &model, double h,
                                                           Progress &progress)
{
    std::vector<int> all(model.surfaces.size());
    std::iota(all.begin(), all.end(), 0);
    const TriangleTree tree(model, all);
    std::vector<std::vector<SideThinArea>> areas(model.regions.size());
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        progress.tick(static_cast<double>(r) / model.regions.size(), "region thickness");
        std::vector<bool> bounds(model.surfaces.size(), false);
        for (const RegionSide &side : model.regions[r].boundaries)
            bounds[side.surface] = true;
        for (const RegionSide &side : model.regions[r].boundaries) {
            const Areas a = sideAreas(model, tree, side, bounds, h);
            areas[r].push_back({side, a.thin, a.all});
        }
    }
    return areas;
}

std::vector<double> regionThinShares(const Model &model, double h, Progress &progress)
{
    const std::vector<std::vector<SideThinArea>> areas = regionSideThinAreas(model, h, progress);
    std::vector<double> shares(model.regions.size(), 0.0);
    for (std::size_t r = 0; r < areas.size(); ++r) {
        double thin = 0.0;
        double all = 0.0;
        for (const SideThinArea &a : areas[r]) {
            thin += a.thin;
            all += a.all;
        }
        shares[r] = all > 0.0 ? thin / all : 0.0;
    }
    return shares;
}

} // namespace stratamesh
