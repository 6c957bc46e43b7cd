#include "remesh/pocket_repair.h"

#include "model/region_shells.h"
#include "model/topology.h"
#include "model/validity.h"

#include <algorithm>
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

// The fan of `triangles` (local ids) of surface s around a vertex of their own, as the loop
// of its outer vertices in the fan's orientation; empty when they are not such a fan.
std::vector<int> fanLoop(const Model &model, int s, const std::vector<int> &triangles, int &centre)
{
    const Surface &surface = model.surfaces[s];
    std::map<int, int> uses;
    for (int t : triangles)
        for (int v : surface.triangles[t])
            ++uses[v];
    centre = -1;
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
    const int a = loop[e], b = loop[(e + 1) % loop.size()];
    // The two triangles on a–b: the new one runs a → b, the other b → a.
    int inside = -1, outside = -1, c = -1, d = -1;
    for (std::size_t t = 0; t < kept.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Triangle &tri = kept[t];
            if (tri[k] == a && tri[(k + 1) % 3] == b) {
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
    for (const Triangle &tri : kept) // the flipped edge c–d must not exist already
        for (int k = 0; k < 3; ++k)
            if ((tri[k] == c && tri[(k + 1) % 3] == d) || (tri[k] == d && tri[(k + 1) % 3] == c))
                return false;
    kept[inside] = {a, d, c};
    kept[outside] = {d, b, c};
    surface.triangles = std::move(kept);
    return true;
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
    for (int guard = 0; guard < 4 * repair.pockets && !shells.pockets.empty(); ++guard) {
        bool changed = false;
        for (const RegionPocket &pocket : shells.pockets) {
            std::map<int, std::vector<int>> bySurface;
            for (const PocketSide &side : pocket.sides)
                bySurface[side.surface].push_back(side.triangle);
            for (const auto &[s, triangles] : bySurface) {
                if (!tried.insert({s, triangles}).second)
                    continue;
                int centre = -1;
                const std::vector<int> loop = fanLoop(model, s, triangles, centre);
                for (std::size_t way = 0; way < 2 * loop.size() && !changed; ++way) {
                    // A try that passes the shells costs a validity check: tick on each.
                    ++tries;
                    Progress step(progress, tries / (tries + 8.0), (tries + 1) / (tries + 9.0),
                                  "opening pockets");
                    // Tried in place on the shells alone (they need no new topology: no
                    // vertex moves), which rejects most tries cheaply.
                    Surface &surface = model.surfaces[s];
                    const std::vector<Triangle> saved = surface.triangles;
                    if (!retriangulate(surface, triangles, loop, way % loop.size(),
                                       way < loop.size()))
                        continue;
                    const RegionShells opened = analyseRegionShells(model);
                    if (opened.pockets.size() >= shells.pockets.size()
                        || opened.folds.size() > shells.folds.size()) {
                        surface.triangles = saved;
                        continue;
                    }
                    Model candidate = recoverTopology(model);
                    surface.triangles = saved;
                    ValidityReport after = checkValidity(candidate, step);
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
        if (!changed)
            break;
        shells = analyseRegionShells(model);
    }
    repair.opened = repair.pockets - static_cast<int>(shells.pockets.size());
    return repair;
}

} // namespace stratamesh
