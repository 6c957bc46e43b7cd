#include "remesh/flat_triangles.h"

#include "model/topology.h"
#include "model/unused_vertices.h"
#include "quality/triangle_quality.h"
#include "remesh/pocket_repair.h"

#include <algorithm>
#include <limits>
#include <set>

namespace stratamesh {

namespace {

struct Flat {
    int apex = -1, p = -1, q = -1; // global vertex ids; the apex lies near the edge p–q
    double angle = 0.0;            // the apex angle
};

std::array<int, 3> globalIds(const Model &model, std::size_t s, const Triangle &t)
{
    const std::vector<int> &g = model.surfaceVertexToGlobal[s];
    return {g[t[0]], g[t[1]], g[t[2]]};
}

// The flattest triangle not tried yet (key: its sorted global ids), or apex -1.
Flat flattest(const Model &model, double apexDeg, const std::set<std::array<int, 3>> &tried)
{
    Flat best;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        for (const Triangle &t : model.surfaces[s].triangles) {
            const std::array<int, 3> g = globalIds(model, s, t);
            const TriangleShape shape =
                triangleShape(model.vertices[g[0]], model.vertices[g[1]], model.vertices[g[2]]);
            const int k =
                static_cast<int>(std::max_element(shape.anglesDeg.begin(), shape.anglesDeg.end())
                                 - shape.anglesDeg.begin());
            if (shape.anglesDeg[k] < apexDeg || shape.anglesDeg[k] <= best.angle)
                continue;
            std::array<int, 3> key = g;
            std::sort(key.begin(), key.end());
            if (tried.count(key))
                continue;
            best = {g[k], g[(k + 1) % 3], g[(k + 2) % 3], shape.anglesDeg[k]};
        }
    return best;
}

double minAngle(const Model &model, const std::array<int, 3> &g)
{
    return triangleMinAngleDeg(model.vertices[g[0]], model.vertices[g[1]], model.vertices[g[2]]);
}

// The model with every triangle on p–q split at the apex and every triangle on all three
// dropped, in `out`; `added` gets, per surface, the ids of the triangles made. False when the
// split would not improve the worst smallest angle or would empty a surface.
bool splitAtApex(const Model &model, const Flat &f, Model &out,
                 std::vector<std::vector<int>> &added)
{
    out = model;
    added.assign(model.surfaces.size(), {});
    double worstBefore = std::numeric_limits<double>::infinity();
    double worstAfter = std::numeric_limits<double>::infinity();
    bool changed = false;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const Surface &in = model.surfaces[s];
        Surface &surface = out.surfaces[s];
        std::vector<Triangle> kept, made;
        int apexLocal = -1;
        for (std::size_t v = 0; v < in.vertices.size(); ++v)
            if (model.surfaceVertexToGlobal[s][v] == f.apex)
                apexLocal = static_cast<int>(v);
        for (const Triangle &t : in.triangles) {
            const std::array<int, 3> g = globalIds(model, s, t);
            int k = -1;
            for (int i = 0; i < 3; ++i)
                if ((g[i] == f.p && g[(i + 1) % 3] == f.q)
                    || (g[i] == f.q && g[(i + 1) % 3] == f.p))
                    k = i;
            if (k < 0) {
                kept.push_back(t);
                continue;
            }
            changed = true;
            worstBefore = std::min(worstBefore, minAngle(model, g));
            if (g[(k + 2) % 3] == f.apex)
                continue; // the flat triangle itself, or its copy in another surface
            if (apexLocal < 0) {
                apexLocal = static_cast<int>(surface.vertices.size());
                surface.vertices.push_back(model.vertices[f.apex]);
            }
            const int a = t[k], b = t[(k + 1) % 3], x = t[(k + 2) % 3];
            made.push_back({a, apexLocal, x});
            made.push_back({apexLocal, b, x});
            const int ga = g[k], gb = g[(k + 1) % 3], gx = g[(k + 2) % 3];
            worstAfter = std::min(
                {worstAfter, minAngle(model, {ga, f.apex, gx}), minAngle(model, {f.apex, gb, gx})});
        }
        if (kept.size() == in.triangles.size())
            continue;
        if (kept.empty() && made.empty())
            return false;
        for (const Triangle &t : made) {
            added[s].push_back(static_cast<int>(kept.size()));
            kept.push_back(t);
        }
        surface.triangles = std::move(kept);
        dropUnusedVertices(surface);
    }
    return changed && worstAfter > worstBefore;
}

// Whether a triangle of `model` has its corners at a, b and c (in any order).
bool holdsTriangleAt(const Model &model, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        for (const Triangle &t : model.surfaces[s].triangles) {
            int found = 0;
            for (int v : globalIds(model, s, t)) {
                const Vec3 &x = model.vertices[v];
                found += x == a || x == b || x == c;
            }
            if (found == 3)
                return true;
        }
    return false;
}

// No check finds more than before (a split that mends one problem of an invalid model and makes
// another is a trade, not a repair: modelA5 at 1000 sites without refinement had a folded
// contact turned into a duplicate triangle).
bool noWorse(const ValidityReport &before, const ValidityReport &after)
{
    if (before.valid && !after.valid)
        return false;
    for (const auto &[check, count] : after.counts)
        if (count > before.count(check))
            return false;
    return true;
}

} // namespace

FlatTriangleRepair mendFlatTriangles(Model &model, ValidityReport &validity, double apexDeg,
                                     int maxTries, Progress &progress)
{
    FlatTriangleRepair repair;
    std::set<std::array<int, 3>> tried;
    for (int attempt = 0; attempt < maxTries; ++attempt) {
        progress.tick(static_cast<double>(attempt) / maxTries);
        const Flat f = flattest(model, apexDeg, tried);
        if (f.apex < 0)
            break;
        std::array<int, 3> key{f.apex, f.p, f.q};
        std::sort(key.begin(), key.end());
        tried.insert(key);
        ++repair.found;
        Model candidate;
        std::vector<std::vector<int>> added;
        if (!splitAtApex(model, f, candidate, added))
            continue;
        candidate = recoverTopology(std::move(candidate));
        ValidityReport after;
        if (validity.problems.empty()) {
            // Without intersections before, only the new triangles can make one.
            bool meets = false;
            for (std::size_t s = 0; s < added.size() && !meets; ++s)
                meets = !added[s].empty()
                        && trianglesMeetOthers(candidate, static_cast<int>(s), added[s]);
            if (meets)
                continue;
            after = checkValidityExceptIntersections(candidate);
        } else {
            after = checkValidity(candidate);
        }
        // The split can close a pocket where another surface leaves the long edge at a small
        // angle; pocket repair opens it (a 10-fault network at 5000 sites: F6_4 by H1_b5, the
        // flat triangle mended only so). It may also open it by making the flat triangle again
        // (modelA5 at 1000 and 2000 sites: f1_4 and h1 21° apart along the long edge), and then
        // the split is not kept.
        if (after.count(validity_check::regionPocket) > 0)
            repairPockets(candidate, after);
        if (holdsTriangleAt(candidate, model.vertices[f.apex], model.vertices[f.p],
                            model.vertices[f.q]))
            continue;
        if (!noWorse(validity, after))
            continue;
        model = std::move(candidate);
        validity = std::move(after);
        ++repair.mended;
    }
    return repair;
}

} // namespace stratamesh
