// What the Voronoi diagram is restricted to (thesis §1.2.1, §4.3): every triangle of every
// surface of a model at once, every segment of its contact and border lines, and its corners,
// over one shared array of points so that surfaces meeting along a contact share its vertices
// (and hence its restricted Voronoi vertices).
#pragma once

#include "model/model.h"

#include <array>
#include <vector>

namespace stratamesh {

struct RestrictionDomain {
    std::vector<Vec3> points;                 // Model::vertices once topology is recovered
    std::vector<Triangle> triangles;          // indices into points
    std::vector<int> triangleSurface;         // surface of each triangle
    std::vector<int> triangleInSurface;       // its index inside Surface::triangles
    std::vector<std::array<int, 2>> segments; // line segments, indices into points
    std::vector<int> segmentLine;             // line of each segment
    std::vector<int> corners;                 // point of each corner (Model::corners order)
    std::vector<double> density;              // ρ per point (> 0); empty means ρ = 1
    int surfaceCount = 0;
    int lineCount = 0;

    // Connectivity inside a surface, from surface-local ids (never from positions): edge e of
    // triangle t (from corner e to corner (e + 1) % 3) has id edgeIds[3t + e]; triangles of one
    // surface sharing a local edge share its id. Filled by finalizeDomain().
    std::vector<int> edgeIds;
    // Segment order along each line: segments of line L are lineSegments[lineOffsets[L] ..
    // lineOffsets[L + 1]), in line order, and lineClosed[L] tells whether the last one joins the
    // first. Filled by finalizeDomain() (segments of one line must be given in line order).
    std::vector<int> lineOffsets;
    std::vector<int> lineSegments;
    std::vector<char> lineClosed;

    double surfaceArea() const;
    double lineLength() const;
};

// All surfaces, lines and corners of a model. With recovered topology, points are the model's
// global vertices and lines/corners are included; without it, each surface gets its own points
// and there are no lines or corners. density, when not empty, has one value per global vertex
// (per concatenated surface vertex without topology). Throws InputError on bad indices,
// non-finite coordinates or non-positive density.
RestrictionDomain makeRestrictionDomain(const Model &model, std::vector<double> density = {});

// Validates a domain assembled by hand and fills edgeIds and the line order. When
// localTriangles is given (one per triangle, surface-local ids) connectivity comes from it,
// otherwise from the point indices. Throws InputError on an inconsistent domain.
void finalizeDomain(RestrictionDomain &domain, const std::vector<Triangle> &localTriangles = {});

} // namespace stratamesh
