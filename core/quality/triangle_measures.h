// Per-element measures of a model for colouring its surfaces and reviewing its worst elements
// (thesis §4.5 judges a remeshing by min angle and quality Q, Table 4.2 and its histograms): one
// value per triangle, the triangles in one histogram bin, the triangles in order of quality, and
// each vertex's distance to another model.
#pragma once

#include "model/model.h"
#include "quality/histogram.h"

#include <vector>

namespace stratamesh {

enum class TriangleMeasure { MinAngle, Quality };

// One value per triangle, surface by surface (indexed like Model::surfaces and
// Surface::triangles). Throws InputError when a triangle refers to a vertex its surface lacks.
std::vector<std::vector<double>> triangleMeasures(const Model &model, TriangleMeasure measure);

struct MeasuredTriangle {
    int surface = -1;
    int triangle = -1;
    double value = 0.0;
    Vec3 centroid = Vec3::Zero();
};

// The triangles counted in `bin` of a histogram of `measure` with these edges, in model order:
// as many as the bar's count, since Histogram::binOf decides both.
std::vector<MeasuredTriangle> trianglesInBin(const Model &model, TriangleMeasure measure,
                                             const Histogram &bins, int bin);

// Every triangle by increasing value (worst first for min angle and Q); ties keep model order.
std::vector<MeasuredTriangle> trianglesByMeasure(const Model &model, TriangleMeasure measure);

// Distance from each vertex of `from` to the nearest triangle of `to`, surface by surface
// (local vertex ids). Throws InputError when `to` has no triangle.
std::vector<std::vector<double>> vertexDistances(const Model &from, const Model &to);

} // namespace stratamesh
