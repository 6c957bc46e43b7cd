// Shape measures of one triangle, as used to compare input and remeshed models (thesis §4.5,
// Table 4.2): the quality Q = 6S / (√3 · hmax · p) of Frey & Borouchaki (1999), "Surface mesh
// quality evaluation", IJNME 45, and the triangle's angles.
#pragma once

#include "model/model.h"

#include <array>

namespace stratamesh {

struct TriangleShape {
    double area = 0.0;
    double longestEdge = 0.0;                       // hmax
    double halfPerimeter = 0.0;                     // p
    std::array<double, 3> anglesDeg{0.0, 0.0, 0.0}; // at a, b, c
    double minAngleDeg = 0.0;
    double maxAngleDeg = 0.0;
    double quality = 0.0; // Q in [0, 1]: 1 equilateral, 0 degenerate
};

// Never throws: a degenerate triangle (collinear or coincident points) has Q = 0 and its zero
// angles, so statistics over real files with needles and slivers stay defined.
TriangleShape triangleShape(const Vec3 &a, const Vec3 &b, const Vec3 &c);

double triangleArea(const Vec3 &a, const Vec3 &b, const Vec3 &c);
double triangleQuality(const Vec3 &a, const Vec3 &b, const Vec3 &c);
double triangleMinAngleDeg(const Vec3 &a, const Vec3 &b, const Vec3 &c);

} // namespace stratamesh
