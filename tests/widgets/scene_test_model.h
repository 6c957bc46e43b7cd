// A small structural model built in code for widget tests: a unit box, one horizon across it
// and one fault, with topology recovered by the core.
#pragma once

#include "model/model.h"
#include "model/topology.h"

#include <functional>

namespace stratamesh::test {

inline Surface gridSurface(const std::string &name, FeatureType type, int n,
                           const std::function<Vec3(double, double)> &at)
{
    Surface s;
    s.name = name;
    s.featureName = name;
    s.sourceObject = name;
    s.type = type;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            s.vertices.push_back(at(double(i) / n, double(j) / n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            s.triangles.push_back({a, b, d});
            s.triangles.push_back({a, d, c});
        }
    return s;
}

// Box [0,2]x[0,2]x[0,1]; horizon z = 0.5 over the whole box; fault x = 1.2 in the upper half.
inline Model sceneTestModel()
{
    Model m;
    m.name = "scene_test";
    m.surfaces.push_back(gridSurface("horizon", FeatureType::Horizon, 8,
                                     [](double u, double v) { return Vec3(2 * u, 2 * v, 0.5); }));
    m.surfaces.push_back(gridSurface("fault", FeatureType::Fault, 4, [](double u, double v) {
        return Vec3(1.2, 2 * u, 0.5 + 0.5 * v);
    }));
    const auto box = [&](const char *name, std::function<Vec3(double, double)> at) {
        m.surfaces.push_back(gridSurface(name, FeatureType::Boundary, 2, at));
    };
    box("bottom", [](double u, double v) { return Vec3(2 * u, 2 * v, 0); });
    box("top", [](double u, double v) { return Vec3(2 * u, 2 * v, 1); });
    box("west", [](double u, double v) { return Vec3(0, 2 * u, v); });
    box("east", [](double u, double v) { return Vec3(2, 2 * u, v); });
    box("south", [](double u, double v) { return Vec3(2 * u, 0, v); });
    box("north", [](double u, double v) { return Vec3(2 * u, 2, v); });
    return recoverTopology(std::move(m));
}

} // namespace stratamesh::test
