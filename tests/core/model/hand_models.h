// Tiny models written by hand for the model tests (a few triangles each).
#pragma once

#include "model/model.h"

#include <initializer_list>
#include <string>

namespace stratamesh::test {

inline Surface makeSurface(const std::string &name, std::initializer_list<Vec3> vertices,
                           std::initializer_list<Triangle> triangles,
                           FeatureType type = FeatureType::Horizon)
{
    Surface s;
    s.name = name;
    s.featureName = name;
    s.sourceObject = name;
    s.type = type;
    s.vertices = vertices;
    s.triangles = triangles;
    return s;
}

// Unit square [0,1]² at height z, two triangles, normal up.
inline Surface square(const std::string &name, double z = 0.0)
{
    return makeSurface(name, {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}, {{0, 1, 2}, {0, 2, 3}});
}

inline Model modelOf(std::initializer_list<Surface> surfaces)
{
    Model m;
    m.name = "hand";
    m.surfaces = surfaces;
    return m;
}

} // namespace stratamesh::test
