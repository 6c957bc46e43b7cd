#include "complexity/angle_measure.h"

#include "complexity/segment_tree.h"
#include "model/surface_edges.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <unordered_map>

namespace stratamesh {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

struct HalfPlane {
    Vec3 v;      // in the triangle, perpendicular to the edge, away from it
    Vec3 normal; // unit right-hand normal of the triangle
    int surface;
};

} // namespace

double wedgeAngle(const Vec3 &v0, const Vec3 &m0, const std::vector<Vec3> &others)
{
    double best = kTwoPi;
    for (const Vec3 &v : others) {
        double theta = std::atan2(v.dot(m0), v.dot(v0));
        if (theta < 0.0)
            theta += kTwoPi;
        // The same half-plane (a surface bounding the region on both sides) is a full turn away.
        if (theta < 1e-9)
            theta = kTwoPi;
        best = std::min(best, theta);
    }
    return best;
}

std::vector<double> regionSharpShares(const Model &model, double alphaDegrees)
{
    const double alpha = alphaDegrees * M_PI / 180.0;
    // Length of each line edge (global vertex pair).
    std::unordered_map<long long, double> lineEdges;
    for (const Line &line : model.lines) {
        for (int k = 0; k < lineSegmentCount(line); ++k) {
            const auto [a, b] = lineSegment(line, k);
            lineEdges[edgeKey(a, b)] = (model.vertices[a] - model.vertices[b]).norm();
        }
    }
    // The half-planes of the triangles around each line edge.
    std::unordered_map<long long, std::vector<HalfPlane>> around;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const Surface &surface = model.surfaces[s];
        const std::vector<int> &global = model.surfaceVertexToGlobal[s];
        for (const Triangle &t : surface.triangles) {
            const Vec3 n = (surface.vertices[t[1]] - surface.vertices[t[0]])
                               .cross(surface.vertices[t[2]] - surface.vertices[t[0]]);
            if (!(n.norm() > 0.0))
                continue;
            for (int k = 0; k < 3; ++k) {
                const long long key = edgeKey(global[t[k]], global[t[(k + 1) % 3]]);
                if (!lineEdges.count(key))
                    continue;
                const Vec3 &a = surface.vertices[t[k]];
                const Vec3 u = (surface.vertices[t[(k + 1) % 3]] - a).normalized();
                const Vec3 c = surface.vertices[t[(k + 2) % 3]] - a;
                around[key].push_back(
                    {(c - c.dot(u) * u).normalized(), n.normalized(), static_cast<int>(s)});
            }
        }
    }

    std::vector<double> shares(model.regions.size(), 0.0);
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        std::multimap<int, double> signs; // surface -> +1 / -1 (both for an internal surface)
        for (const RegionSide &side : model.regions[r].boundaries)
            signs.emplace(side.surface, side.positive ? 1.0 : -1.0);
        double total = 0.0;
        double sharp = 0.0;
        for (const auto &[key, planes] : around) {
            std::vector<std::pair<Vec3, Vec3>> mine; // (v, inward normal)
            for (const HalfPlane &p : planes) {
                const auto range = signs.equal_range(p.surface);
                for (auto it = range.first; it != range.second; ++it)
                    mine.emplace_back(p.v, it->second * p.normal);
            }
            if (mine.empty())
                continue;
            double narrowest = kTwoPi;
            for (std::size_t i = 0; i < mine.size(); ++i) {
                std::vector<Vec3> others;
                for (std::size_t j = 0; j < mine.size(); ++j)
                    if (j != i)
                        others.push_back(mine[j].first);
                narrowest = std::min(narrowest, wedgeAngle(mine[i].first, mine[i].second, others));
            }
            const double length = lineEdges.at(key);
            total += length;
            if (narrowest < alpha)
                sharp += length;
        }
        shares[r] = total > 0.0 ? sharp / total : 0.0;
    }
    return shares;
}

double surfaceSharpCornerShare(const Model &model, int surface, double alphaDegrees)
{
    const double alpha = alphaDegrees * M_PI / 180.0;
    const Surface &s = model.surfaces[surface];
    std::vector<bool> cornerVertex(model.vertices.size(), false);
    for (int l : s.lines)
        for (int c : model.lines[l].corners)
            if (c >= 0)
                cornerVertex[model.corners[c].vertex] = true;
    // Sum of the triangle angles at each local vertex lying on a corner.
    std::map<int, double> angleAt;
    const std::vector<int> &global = model.surfaceVertexToGlobal[surface];
    for (const Triangle &t : s.triangles) {
        for (int k = 0; k < 3; ++k) {
            if (!cornerVertex[global[t[k]]])
                continue;
            const Vec3 &p = s.vertices[t[k]];
            const Vec3 a = s.vertices[t[(k + 1) % 3]] - p;
            const Vec3 b = s.vertices[t[(k + 2) % 3]] - p;
            if (!(a.norm() > 0.0 && b.norm() > 0.0))
                continue;
            angleAt[t[k]] += std::atan2(a.cross(b).norm(), a.dot(b));
        }
    }
    if (angleAt.empty())
        return 0.0;
    int sharp = 0;
    for (const auto &[vertex, angle] : angleAt)
        if (angle < alpha)
            ++sharp;
    return static_cast<double>(sharp) / angleAt.size();
}

} // namespace stratamesh
