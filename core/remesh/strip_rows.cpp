#include "remesh/strip_rows.h"

#include "quality/triangle_quality.h"
#include "remesh/intersection_repair.h"
#include "remesh/mesh_cleanup.h"
#include "remesh/mesh_smoothing.h"

#include <algorithm>
#include <set>
#include <utility>

namespace stratamesh {

namespace {

int trianglesBelow(const EditableSoup &soup, double angleDeg)
{
    int n = 0;
    for (int t = 0; t < soup.triangleCapacity(); ++t) {
        if (!soup.alive(t))
            continue;
        const auto &v = soup.triangle(t).v;
        if (triangleMinAngleDeg(soup.position(v[0]), soup.position(v[1]), soup.position(v[2]))
            < angleDeg)
            ++n;
    }
    return n;
}

// The rungs of the strip triangles: (a, b) and (a, c) of a triangle whose only feature edge is
// (b, c) and whose apex a lies on another line, with the angle at a under the limit.
std::set<std::pair<int, int>> stripRungs(const EditableSoup &soup, double minAngleDeg)
{
    std::set<std::pair<int, int>> rungs;
    for (int t = 0; t < soup.triangleCapacity(); ++t) {
        if (!soup.alive(t))
            continue;
        const auto &v = soup.triangle(t).v;
        for (int k = 0; k < 3; ++k) {
            const int a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
            if (!soup.isFeatureEdge(b, c) || soup.isFeatureEdge(a, b) || soup.isFeatureEdge(a, c)
                || soup.vertexClass(a) == VertexClass::Interior
                || triangleShape(soup.position(a), soup.position(b), soup.position(c)).anglesDeg[0]
                       >= minAngleDeg)
                continue;
            for (int e : {b, c})
                if (soup.vertexClass(e) != VertexClass::Interior)
                    rungs.insert({std::min(a, e), std::max(a, e)});
        }
    }
    return rungs;
}

} // namespace

int addStripRows(EditableSoup &soup, InputProjector &projector, const StripRowParams &params,
                 Progress &progress)
{
    const std::set<std::pair<int, int>> rungs = stripRungs(soup, params.minAngleDeg);
    if (rungs.empty())
        return 0;
    const EditableSoup start = soup;
    const int below = trianglesBelow(soup, params.minAngleDeg);
    int added = 0;
    std::vector<int> row;
    for (const auto &[u, w] : rungs) {
        const std::vector<int> on = soup.edgeTriangles(u, w);
        if (on.size() != 2)
            continue;
        const int surface = soup.triangle(on.front()).surface;
        const Vec3 middle = 0.5 * (soup.position(u) + soup.position(w));
        OutputPoint p;
        p.position = projector.onSurface(surface, middle, middle);
        p.origin = PointOrigin::Surface;
        p.surfaces = {surface};
        row.push_back(soup.addPoint(p));
        soup.splitEdge(u, w, row.back());
        ++added;
    }
    // Consecutive rungs share an end, so the middles are half as far apart as the line points:
    // every other one goes, merged with its neighbour in the row at their middle.
    std::set<int> inRow(row.begin(), row.end()), merged;
    for (int x : row) {
        if (merged.count(x) || soup.vertexTriangles(x).empty())
            continue;
        for (int y : soup.neighbours(x)) {
            if (!inRow.count(y) || merged.count(y))
                continue;
            const int surface = soup.triangle(soup.vertexTriangles(x).front()).surface;
            const Vec3 middle = 0.5 * (soup.position(x) + soup.position(y));
            if (soup.collapse(x, y, projector.onSurface(surface, middle, middle), 0.05)) {
                merged.insert(x);
                merged.insert(y);
                --added;
                break;
            }
        }
    }
    // Each of these is a pass over the whole soup (0.2 s on modelA5 at 5000 sites): ticks between.
    SmoothingParams smoothing;
    smoothing.passes = params.relaxPasses;
    {
        Progress relaxing(progress, 0.0, 0.5, "relaxing");
        relaxVertices(soup, projector, smoothing, relaxing);
    }
    progress.tick(0.5, "flips");
    improveByFlips(soup);
    if (trianglesBelow(soup, params.minAngleDeg) >= below) {
        soup = start;
        return 0;
    }
    progress.tick(0.7, "crossings");
    const std::size_t crossings = soupIntersections(soup).size();
    progress.tick(0.85, "crossings before");
    if (CrossingsAtStart(start).exceededBy(crossings)) {
        soup = start;
        return 0;
    }
    return added;
}

} // namespace stratamesh
