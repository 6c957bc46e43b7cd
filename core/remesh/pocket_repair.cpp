#include "remesh/pocket_repair.h"

#include "model/region_shells.h"
#include "model/surface_edges.h"
#include "model/topology.h"
#include "model/unused_vertices.h"
#include "model/validity.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace stratamesh {

namespace {

// True when `after` has fewer problems than `before` and no more of any check.
bool better(const ValidityReport &after, const ValidityReport &before)
{
    std::size_t a = 0, b = 0;
    for (const auto &[check, count] : after.counts) {
        if (count > before.count(check))
            return false;
        a += count;
    }
    for (const auto &[check, count] : before.counts)
        b += count;
    return a < b;
}

// The triangles of `after` (ids in it) whose vertex sets none of `before` has.
std::vector<int> addedTriangles(const std::vector<Triangle> &before, const Surface &after)
{
    auto key = [](const Triangle &t) { return sortedTriangle(t[0], t[1], t[2]); };
    std::set<std::array<int, 3>> old;
    for (const Triangle &t : before)
        old.insert(key(t));
    std::vector<int> added;
    for (std::size_t t = 0; t < after.triangles.size(); ++t)
        if (!old.count(key(after.triangles[t])))
            added.push_back(static_cast<int>(t));
    return added;
}

// The fan of `triangles` (local ids) of surface s around a vertex of their own, as the loop
// of its outer vertices in the fan's orientation; empty when they are not such a fan.
std::vector<int> fanLoop(const Model &model, int s, const std::vector<int> &triangles)
{
    const Surface &surface = model.surfaces[s];
    std::map<int, int> uses;
    for (int t : triangles)
        for (int v : surface.triangles[t])
            ++uses[v];
    int centre = -1;
    for (const auto &[v, n] : uses)
        if (n == static_cast<int>(triangles.size()))
            centre = v;
    if (centre < 0 || triangles.size() < 3)
        return {};
    // The centre is the surface's own (no other surface holds it) and the fan is all around it.
    const int g = model.surfaceVertexToGlobal[s][centre];
    for (std::size_t o = 0; o < model.surfaces.size(); ++o)
        if (static_cast<int>(o) != s)
            for (int other : model.surfaceVertexToGlobal[o])
                if (other == g)
                    return {};
    int around = 0;
    for (const Triangle &t : surface.triangles)
        around += std::count(t.begin(), t.end(), centre) > 0 ? 1 : 0;
    if (around != static_cast<int>(triangles.size()))
        return {};
    std::map<int, int> next; // a → b for each fan triangle (a, b, centre) in its orientation
    for (int t : triangles) {
        const Triangle &tri = surface.triangles[t];
        const int k = static_cast<int>(std::find(tri.begin(), tri.end(), centre) - tri.begin());
        next[tri[(k + 1) % 3]] = tri[(k + 2) % 3];
    }
    std::vector<int> loop{next.begin()->first};
    while (loop.size() <= next.size()) {
        const auto it = next.find(loop.back());
        if (it == next.end())
            return {};
        if (it->second == loop.front())
            break;
        loop.push_back(it->second);
    }
    return loop.size() == next.size() ? loop : std::vector<int>{};
}

// Flips the edge a–b of a surface: its triangle running a → b and the one running b → a become
// the two on the other diagonal. False when the edge is not on exactly two triangles running it
// both ways, or the other diagonal is an edge already.
bool flipEdge(std::vector<Triangle> &triangles, int a, int b)
{
    int inside = -1, outside = -1, c = -1, d = -1;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Triangle &tri = triangles[t];
            if (tri[k] == a && tri[(k + 1) % 3] == b) {
                if (inside >= 0)
                    return false;
                inside = static_cast<int>(t);
                c = tri[(k + 2) % 3];
            } else if (tri[k] == b && tri[(k + 1) % 3] == a) {
                if (outside >= 0)
                    return false; // not a manifold edge of this surface
                outside = static_cast<int>(t);
                d = tri[(k + 2) % 3];
            }
        }
    if (inside < 0 || outside < 0 || c == d)
        return false;
    for (const Triangle &tri : triangles)
        for (int k = 0; k < 3; ++k)
            if ((tri[k] == c && tri[(k + 1) % 3] == d) || (tri[k] == d && tri[(k + 1) % 3] == c))
                return false;
    triangles[inside] = {a, d, c};
    triangles[outside] = {d, b, c};
    return true;
}

// Flips the loop edge (loop[e], loop[e+1]) out of the surface, with the surface's other triangle
// on it; first, when `withoutCentre`, replaces the fan by a fan from the loop's first vertex.
// False when it cannot.
bool retriangulate(Surface &surface, const std::vector<int> &fan, const std::vector<int> &loop,
                   std::size_t e, bool withoutCentre)
{
    std::vector<Triangle> kept;
    std::set<int> removed;
    if (withoutCentre)
        removed.insert(fan.begin(), fan.end());
    for (std::size_t t = 0; t < surface.triangles.size(); ++t)
        if (!removed.count(static_cast<int>(t)))
            kept.push_back(surface.triangles[t]);
    if (withoutCentre)
        for (std::size_t k = 1; k + 1 < loop.size(); ++k)
            kept.push_back({loop[0], loop[k], loop[k + 1]});
    if (!flipEdge(kept, loop[e], loop[(e + 1) % loop.size()]))
        return false;
    surface.triangles = std::move(kept);
    return true;
}

// One way to change a surface's triangles around a pocket: a fan re-triangulation (fanWay <
// 2·loop size, see retriangulate), or a flip of the edge a → b of one of its triangles.
struct PocketEdit {
    int fanWay = -1;
    int a = -1, b = -1;
};

// The fan re-triangulations when the pocket's triangles in the surface are a fan, then the flip
// of every edge of those triangles: pockets closed by a fold of two surfaces along a longer
// contact, not by a fan, open by flipping one of their edges.
std::vector<PocketEdit> pocketEdits(const Surface &surface, const std::vector<int> &triangles,
                                    const std::vector<int> &loop)
{
    std::vector<PocketEdit> edits;
    for (std::size_t way = 0; way < 2 * loop.size(); ++way)
        edits.push_back({static_cast<int>(way), -1, -1});
    std::set<std::pair<int, int>> seen;
    for (int t : triangles) {
        const Triangle &tri = surface.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            if (seen.insert({std::min(a, b), std::max(a, b)}).second)
                edits.push_back({-1, a, b});
        }
    }
    return edits;
}

bool applyEdit(Surface &surface, const std::vector<int> &triangles, const std::vector<int> &loop,
               const PocketEdit &edit)
{
    if (edit.fanWay >= 0)
        return retriangulate(surface, triangles, loop, std::size_t(edit.fanWay) % loop.size(),
                             std::size_t(edit.fanWay) < loop.size());
    return flipEdge(surface.triangles, edit.a, edit.b);
}

} // namespace

PocketRepair repairPockets(Model &model, ValidityReport &validity, Progress &progress)
{
    PocketRepair repair;
    RegionShells shells = analyseRegionShells(model);
    repair.pockets = static_cast<int>(shells.pockets.size());
    if (shells.pockets.empty())
        return repair;
    // One pocket at a time, from a fresh analysis: each kept change moves triangle ids.
    std::set<std::pair<int, std::vector<int>>> tried;
    int tries = 0;
    bool changedSinceRetry = false;
    for (int guard = 0; guard < 4 * repair.pockets && !shells.pockets.empty(); ++guard) {
        bool changed = false;
        const std::vector<int> holders = vertexSurfaceCounts(model);
        for (const RegionPocket &pocket : shells.pockets) {
            std::map<int, std::vector<int>> bySurface;
            for (const PocketSide &side : pocket.sides)
                bySurface[side.surface].push_back(side.triangle);
            for (const auto &[s, triangles] : bySurface) {
                if (!tried.insert({s, triangles}).second)
                    continue;
                const std::vector<int> loop = fanLoop(model, s, triangles);
                const std::vector<PocketEdit> edits =
                    pocketEdits(model.surfaces[s], triangles, loop);
                for (std::size_t e = 0; e < edits.size() && !changed; ++e) {
                    // Most flips of a large pocket (a region piece cut off by a fault) stay
                    // inside its surface and cannot open it (network5 with faults of 20°
                    // dip at 5000 sites: 9,575 of 14,783 tries, 5 ms each).
                    if (edits[e].fanWay < 0
                        && flipKeepsShells(model, s, holders, edits[e].a, edits[e].b))
                        continue;
                    // A try that passes the shells costs a validity check: tick on each.
                    ++tries;
                    Progress step(progress, tries / (tries + 8.0), (tries + 1) / (tries + 9.0),
                                  "opening pockets");
                    // Tried in place on the shells alone (they need no new topology: no
                    // vertex moves), which rejects most tries cheaply.
                    Surface &surface = model.surfaces[s];
                    const std::vector<Triangle> saved = surface.triangles;
                    if (!applyEdit(surface, triangles, loop, edits[e]))
                        continue;
                    const RegionShells opened = analyseRegionShells(model);
                    if (opened.pockets.size() >= shells.pockets.size()
                        || opened.folds.size() > shells.folds.size()) {
                        surface.triangles = saved;
                        continue;
                    }
                    Model candidate = recoverTopology(model);
                    surface.triangles = saved;
                    // `better` never takes an intersection on a model without one, and a new
                    // triangle crossing the model is found on the new triangles alone (modelA5
                    // at 5000 sites: 17 of 33 tries, each a 0.05 s full check); when they cross
                    // nothing, the rest of the model crosses nothing either.
                    const bool clean = validity.count(validity_check::surfaceIntersection) == 0
                                       && s < static_cast<int>(candidate.surfaces.size())
                                       && candidate.surfaces[s].vertices == surface.vertices;
                    if (clean
                        && trianglesMeetOthers(candidate, s,
                                               addedTriangles(saved, candidate.surfaces[s])))
                        continue;
                    ValidityReport after = clean ? checkValidityExceptIntersections(candidate, step)
                                                 : checkValidity(candidate, step);
                    if (better(after, validity)) {
                        model = std::move(candidate);
                        validity = std::move(after);
                        changed = true;
                    }
                }
                if (changed)
                    break;
            }
            if (changed)
                break;
        }
        if (changed) {
            changedSinceRetry = true;
            shells = analyseRegionShells(model);
            continue;
        }
        // Tries that failed before the changes may succeed on the changed model: once more,
        // when no untried edit is left. Not after each change: a few pockets that cannot be
        // opened would be tried again after each of the others (an 8-fault network at 2000
        // sites with its strips kept: 23,000 tries for 101 pockets, 5 minutes).
        if (!changedSinceRetry)
            break;
        changedSinceRetry = false;
        tried.clear();
    }
    repair.opened = repair.pockets - static_cast<int>(shells.pockets.size());
    // A fan replaced without its centre leaves the centre in its surface, used by no triangle.
    int dropped = 0;
    for (Surface &surface : model.surfaces)
        dropped += dropUnusedVertices(surface);
    if (dropped > 0) {
        model = recoverTopology(std::move(model));
        if (!validity.valid) // its problems may name the old vertex ids
            validity = checkValidity(model);
    }
    return repair;
}

} // namespace stratamesh
