// Resolution of intersecting output triangles by edge flips or vertex moves (thesis §4.4.5:
// "they must be identified and the intersections must be resolved by vertex displacements or
// edge flipping"). When neither works, the shortest edge of an intersecting triangle is
// collapsed — the points are closer than the resolution — and recorded. What stays unresolved
// is reported as intersection_unresolved records.
#pragma once

#include "common/progress.h"

#include "remesh/editable_soup.h"
#include "remesh/simplification_ledger.h"

#include <cstddef>
#include <optional>

namespace stratamesh {

struct IntersectionRepairParams {
    int maxRounds = 5;
    double minQuality = 0.05; // moves and flips may not create worse triangles than this
    bool allowMerges =
        true; // then collapse edges of what still intersects (close_feature_merge records)
};

struct IntersectionRepairResult {
    int found = 0; // intersecting pairs before repair
    int resolved = 0;
    int unresolved = 0; // pairs left, each a ledger record
};

IntersectionRepairResult repairIntersections(EditableSoup &soup, const Model &input,
                                             const IntersectionRepairParams &params,
                                             SimplificationLedger &ledger,
                                             Progress &progress = Progress::none());

// Intersecting pairs with a triangle around one of the vertices (a linear scan: for a few).
int intersectionsAroundVertices(const EditableSoup &soup, const std::vector<int> &vertices);

// Pairs of alive triangles of the soup that intersect (triangle ids of the soup).
std::vector<std::pair<int, int>> soupIntersections(const EditableSoup &soup);

// The crossing pairs of a soup kept as a post-processing step's start, searched for only when a
// result with crossings is compared with it: the search of a whole soup is most of such a step's
// time, and most results have no crossing at all. The soup must outlive the count.
class CrossingsAtStart {
public:
    explicit CrossingsAtStart(const EditableSoup &start) : start_(start) {}

    // Whether a result with `pairs` crossing pairs has more than the start (never when 0).
    bool exceededBy(std::size_t pairs);

private:
    const EditableSoup &start_;
    std::optional<std::size_t> count_;
};

} // namespace stratamesh
