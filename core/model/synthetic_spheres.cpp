// Two concentric icospheres: a closed-surface fixture with no line and no corner.
#include "model/synthetic_models.h"

#include "common/error.h"

#include <cmath>
#include <map>

namespace stratamesh {

namespace {

// Unit icosphere, faces counter-clockwise seen from outside (outward normals).
void icosphere(int subdivisions, std::vector<Vec3> &vertices, std::vector<Triangle> &triangles)
{
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3 &v : vertices)
        v.normalize();
    triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int a, int b) {
            const std::pair<int, int> key(std::min(a, b), std::max(a, b));
            auto it = midpoints.find(key);
            if (it != midpoints.end())
                return it->second;
            vertices.push_back((vertices[a] + vertices[b]).normalized());
            const int id = static_cast<int>(vertices.size()) - 1;
            midpoints.emplace(key, id);
            return id;
        };
        std::vector<Triangle> finer;
        finer.reserve(triangles.size() * 4);
        for (const Triangle &f : triangles) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                      ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        triangles.swap(finer);
    }
}

Surface sphere(const std::string &name, FeatureType type, const Vec3 &centre, double radius,
               int subdivisions)
{
    Surface s;
    s.name = name;
    s.featureName = name;
    s.sourceObject = name;
    s.type = type;
    icosphere(subdivisions, s.vertices, s.triangles);
    for (Vec3 &v : s.vertices)
        v = centre + radius * v;
    return s;
}

} // namespace

Model nestedSpheres(const NestedSpheresParams &p)
{
    if (!(p.innerRadius > 0 && p.outerRadius > p.innerRadius))
        throw InputError("nested spheres: the radii must satisfy 0 < inner < outer");
    const bool middle = p.middleRadius > 0;
    if (middle && !(p.middleRadius > p.innerRadius && p.middleRadius < p.outerRadius))
        throw InputError("nested spheres: the middle radius must be between inner and outer");
    if (p.subdivisions < 0 || p.subdivisions > 8)
        throw InputError("nested spheres: subdivisions must be in [0, 8]");
    Model model;
    model.name = "nested_spheres";
    model.surfaces.push_back(
        sphere("inner", FeatureType::Horizon, p.centre, p.innerRadius, p.subdivisions));
    model.surfaces.push_back(
        sphere("outer", FeatureType::Boundary, p.centre, p.outerRadius, p.subdivisions));
    if (middle)
        model.surfaces.push_back(
            sphere("middle", FeatureType::Horizon, p.centre, p.middleRadius, p.subdivisions));
    if (p.withRegions && middle) {
        model.regions.push_back({"inner", {{0, false}}});
        model.regions.push_back({"shell", {{0, true}, {2, false}}});
        model.regions.push_back({"shell2", {{2, true}, {1, false}}});
        model.universe = {{1, true}};
        model.layers.push_back({"all", {0, 1, 2}});
    } else if (p.withRegions) {
        // Normals point outwards: a region inside a sphere is on its negative side.
        model.regions.push_back({"inner", {{0, false}}});
        model.regions.push_back({"shell", {{0, true}, {1, false}}});
        model.universe = {{1, true}};
        model.layers.push_back({"all", {0, 1}});
    }
    return model;
}

} // namespace stratamesh
