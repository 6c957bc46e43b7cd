#include "complexity/cell_element_counts.h"

#include "common/error.h"
#include "common/union_find.h"
#include "complexity/box_elements.h"
#include "complexity/convex_clip.h"
#include "complexity/region_locator.h"
#include "complexity/segment_tree.h"
#include "complexity/triangle_tree.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace stratamesh {

namespace {

Box3 paddedBounds(const ConvexPolyhedron &cell)
{
    Box3 b = cell.bounds();
    const Vec3 pad = Vec3::Constant(2.0 * cell.tolerance());
    return Box3(b.min() - pad, b.max() + pad);
}

constexpr int kLocateLater = -1;

struct Counter {
    const Model &model;
    const TriangleTree &triangles;
    const SegmentTree &segments;

    const std::vector<bool> &isBox;

    // Pieces of inner surfaces, and all the surfaces met, box ones included (for the regions).
    int surfacePieces(const ConvexPolyhedron &cell, const Box3 &bounds, std::vector<int> &met) const
    {
        std::vector<TriangleRef> in;
        for (const TriangleRef &r : triangles.trianglesInBox(bounds)) {
            const Surface &s = model.surfaces[r.surface];
            const Triangle &t = s.triangles[r.triangle];
            if (!triangleMeetsCell(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]], cell))
                continue;
            if (isBox[r.surface])
                met.push_back(r.surface);
            else
                in.push_back(r);
        }
        // Keys (surface, local a, local b) of edges meeting the cell and (surface, v, -1) of
        // vertices in it, with the triangle holding them; equal keys join their triangles.
        std::vector<std::pair<std::array<int, 3>, int>> keys;
        for (int i = 0; i < static_cast<int>(in.size()); ++i) {
            const Surface &s = model.surfaces[in[i].surface];
            const Triangle &t = s.triangles[in[i].triangle];
            for (int k = 0; k < 3; ++k) {
                const int a = t[k];
                const int b = t[(k + 1) % 3];
                if (cell.contains(s.vertices[a]))
                    keys.push_back({{in[i].surface, a, -1}, i});
                if (segmentMeetsCell(s.vertices[a], s.vertices[b], cell))
                    keys.push_back({{in[i].surface, std::min(a, b), std::max(a, b)}, i});
            }
        }
        std::sort(keys.begin(), keys.end());
        UnionFind uf(static_cast<int>(in.size()));
        for (std::size_t k = 1; k < keys.size(); ++k)
            if (keys[k].first == keys[k - 1].first)
                uf.join(keys[k].second, keys[k - 1].second);
        int pieces = 0;
        for (int i = 0; i < static_cast<int>(in.size()); ++i) {
            if (uf.find(i) == i)
                ++pieces;
            met.push_back(in[i].surface);
        }
        return pieces;
    }

    int linePieces(const ConvexPolyhedron &cell, const Box3 &bounds) const
    {
        std::vector<SegmentRef> in;
        for (const SegmentRef &r : segments.segmentsInBox(bounds)) {
            const auto [a, b] = lineSegment(model.lines[r.line], r.segment);
            if (segmentMeetsCell(model.vertices[a], model.vertices[b], cell))
                in.push_back(r);
        }
        int pieces = 0;
        for (std::size_t begin = 0; begin < in.size();) {
            std::size_t end = begin;
            while (end < in.size() && in[end].line == in[begin].line)
                ++end;
            const Line &line = model.lines[in[begin].line];
            const int n = lineSegmentCount(line);
            int count = static_cast<int>(end - begin);
            int joins = 0;
            // Sorted segment ids: consecutive ids are neighbours; for a closed line so are the
            // last and the first.
            auto joined = [&](int k) { // segments k and k + 1 (mod n) through vertex k + 1
                return cell.contains(model.vertices[line.vertices[(k + 1) % line.vertices.size()]]);
            };
            for (std::size_t i = begin + 1; i < end; ++i)
                if (in[i].segment == in[i - 1].segment + 1 && joined(in[i - 1].segment))
                    ++joins;
            if (line.closed && count > 1 && in[begin].segment == 0 && in[end - 1].segment == n - 1
                && joined(n - 1))
                ++joins;
            pieces += std::max(count - joins, 1);
            begin = end;
        }
        return pieces;
    }

    CellElementCounts count(const ConvexPolyhedron &cell) const
    {
        CellElementCounts c;
        if (cell.empty())
            return c;
        const Box3 bounds = paddedBounds(cell);
        std::vector<int> met;
        c.surfaces = surfacePieces(cell, bounds, met);
        c.lines = linePieces(cell, bounds);
        std::vector<int> regions;
        std::sort(met.begin(), met.end());
        met.erase(std::unique(met.begin(), met.end()), met.end());
        for (int s : met)
            regions.insert(regions.end(), model.surfaces[s].regions.begin(),
                           model.surfaces[s].regions.end());
        std::sort(regions.begin(), regions.end());
        regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
        // No inner surface: one region, found later for all such neighbouring cells at once.
        c.regions = regions.empty() ? kLocateLater : static_cast<int>(regions.size());
        return c;
    }
};

// The cell of each inner corner: the one of its nearest site (ties: the smaller index).
std::vector<int> cornersPerCell(const Model &model, const std::vector<int> &corners,
                                const std::vector<Vec3> &sites)
{
    std::vector<int> perCell(sites.size(), 0);
    for (int c : corners) {
        const Vec3 &p = model.vertices[model.corners[c].vertex];
        int best = -1;
        double bestDistance = 0.0;
        for (std::size_t i = 0; i < sites.size(); ++i) {
            const double d = (sites[i] - p).squaredNorm();
            if (best < 0 || d < bestDistance) {
                best = static_cast<int>(i);
                bestDistance = d;
            }
        }
        if (best >= 0)
            ++perCell[best];
    }
    return perCell;
}

// Cells meeting no inner surface lie in one region each, and two such cells sharing a face lie
// in the same one: one ray per group of them (from its first site) instead of one per cell.
void locateRegions(const RegionLocator &locator, const std::vector<Vec3> &sites,
                   const std::vector<ConvexPolyhedron> &cells,
                   std::vector<CellElementCounts> &counts)
{
    std::vector<int> stack;
    for (std::size_t seed = 0; seed < cells.size(); ++seed) {
        if (counts[seed].regions != kLocateLater)
            continue;
        const int found = locator.regionAt(sites[seed]) >= 0 ? 1 : 0;
        counts[seed].regions = found;
        stack.assign(1, static_cast<int>(seed));
        while (!stack.empty()) {
            const int i = stack.back();
            stack.pop_back();
            for (const HalfSpace &face : cells[i].planes()) {
                if (face.tag >= 0 && face.tag < static_cast<int>(counts.size())
                    && counts[face.tag].regions == kLocateLater) {
                    counts[face.tag].regions = found;
                    stack.push_back(face.tag);
                }
            }
        }
    }
}

} // namespace

std::vector<CellElementCounts> countElementsInCells(const Model &model,
                                                    const std::vector<Vec3> &sites,
                                                    const std::vector<ConvexPolyhedron> &cells,
                                                    Progress &progress)
{
    if (sites.size() != cells.size())
        throw InputError("cell counts: " + std::to_string(sites.size()) + " sites but "
                         + std::to_string(cells.size()) + " cells");
    const BoxElements box = boxElements(model);
    std::vector<int> all(model.surfaces.size());
    std::iota(all.begin(), all.end(), 0);
    const TriangleTree triangles(model, all);
    const SegmentTree segments(model, box.innerLines());
    const RegionLocator locator(model);
    const Counter counter{model, triangles, segments, box.surface};
    const std::vector<int> corners = cornersPerCell(model, box.innerCorners(), sites);

    std::vector<CellElementCounts> counts(cells.size());
    const std::size_t chunk = 2048;
    for (std::size_t first = 0; first < cells.size(); first += chunk) {
        progress.tick(static_cast<double>(first) / cells.size(), "counting elements per cell");
        const std::size_t last = std::min(cells.size(), first + chunk);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 16),
                          [&](const tbb::blocked_range<std::size_t> &r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  counts[i] = counter.count(cells[i]);
                                  counts[i].corners = corners[i];
                              }
                          });
    }
    locateRegions(locator, sites, cells, counts);
    progress.tick(1.0, "counting elements per cell");
    return counts;
}

} // namespace stratamesh
