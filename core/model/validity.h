// Validity of a B-Rep model (thesis §3.2: "elements must intersect only along their boundaries and
// elements of the same dimension must have the same geometry on these boundaries"; the input
// requirement of chapter 4 is a valid model with conformal surface meshes). The checks follow the
// spirit of RINGMesh's geomodel_validity (formats.md §3.4) but are exact: vertices are merged by
// exact position and intersections use CGAL's exact predicates, no tolerance anywhere.
#pragma once

#include "common/message_text.h"
#include "common/progress.h"
#include "model/model.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace stratamesh {

// Check names, as they appear in ValidityProblem::check.
namespace validity_check {
// A surface border edge that touches no other surface (nor the same surface elsewhere) on a
// surface that does not lie inside one region (listed with both signs by one region).
inline constexpr const char *notSealed = "not_sealed";
// A local edge with more than two triangles of one surface around it.
inline constexpr const char *nonManifoldEdge = "non_manifold_edge";
// A triangle with a repeated vertex (id or position) or zero area (exactly collinear corners).
inline constexpr const char *degenerateTriangle = "degenerate_triangle";
// Two triangles on the same three points, in one surface or in two.
inline constexpr const char *duplicateTriangle = "duplicate_triangle";
// Two triangles of one surface running their common edge the same way.
inline constexpr const char *inconsistentOrientation = "inconsistent_orientation";
// Two triangles meeting elsewhere than along the vertices and edge they share.
inline constexpr const char *surfaceIntersection = "surface_intersection";
// A region boundary that is not closed or whose sides disagree with the surface normals.
inline constexpr const char *regionBoundary = "region_boundary";
// Region sides that disagree with the geometry around an edge: two surfaces folded over each
// other along a contact, so that one space between them is given to two regions.
inline constexpr const char *foldedContact = "folded_contact";
// A region in more than one piece: a pocket that one seed per region (TetGen's -A) leaves
// without a region.
inline constexpr const char *regionPocket = "region_pocket";
// Two distinct points closer than kCloseVertexTolerance × the bounding-box diagonal: volume
// meshers (TetGen's -T) merge them, which makes duplicated or crossing facets of the triangles.
inline constexpr const char *closeVertices = "close_vertices";
} // namespace validity_check

// TetGen 1.5's default point-merge tolerance, relative to the bounding-box diagonal.
inline constexpr double kCloseVertexTolerance = 1e-8;

struct ValidityProblem {
    std::string check;                 // one of validity_check::*
    std::vector<std::string> entities; // names of the surfaces/lines/regions involved
    Vec3 position = Vec3::Zero();      // where to look (z-up model coordinates)
    std::string message;               // text.text()
    MessageText text;                  // the same, for a translation
};

struct ValidityReport {
    bool valid = true;
    // At most kMaxListedPerCheck problems of each check are listed ...
    std::vector<ValidityProblem> problems;
    // ... but all are counted here (only checks that found something have an entry).
    std::map<std::string, std::size_t> counts;

    std::size_t count(const std::string &check) const
    {
        auto it = counts.find(check);
        return it == counts.end() ? 0 : it->second;
    }
    static constexpr std::size_t kMaxListedPerCheck = 100;
};

// Runs every check. Works on a model with or without topology (recovered on a copy if needed).
// Throws Cancelled when progress is cancelled, InputError when topology cannot be recovered.
ValidityReport checkValidity(const Model &model, Progress &progress = Progress::none());

// Every check but surface_intersection: for an edit of one surface on a model without
// intersections whose new triangles trianglesMeetOthers (below) has cleared, the full check would
// find none again, and that search is most of its time.
ValidityReport checkValidityExceptIntersections(const Model &model,
                                                Progress &progress = Progress::none());

// Whether one of `triangles` (local ids) of `surface` meets another triangle of the model outside
// the vertices and edge they share: the surface_intersection test of checkValidity on those
// triangles only, for edits that must not add an intersection. The model needs its topology.
bool trianglesMeetOthers(const Model &model, int surface, const std::vector<int> &triangles);

} // namespace stratamesh
