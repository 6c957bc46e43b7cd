#include "remesh/strip_collapse.h"

#include "common/translate_noop.h"
#include "model/topology.h"
#include "model/validity.h"
#include "quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

namespace stratamesh {

namespace {

// A polyline with its arc lengths, for projections and points at a parameter.
struct Polyline {
    std::vector<Vec3> points;
    std::vector<double> arc; // arc length at each point

    explicit Polyline(std::vector<Vec3> p) : points(std::move(p)), arc(points.size(), 0.0)
    {
        for (std::size_t i = 1; i < points.size(); ++i)
            arc[i] = arc[i - 1] + (points[i] - points[i - 1]).norm();
    }
    double length() const { return arc.back(); }
    double project(const Vec3 &x) const
    {
        double best = std::numeric_limits<double>::max(), t = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i) {
            const Vec3 d = points[i] - points[i - 1];
            const double dd = d.squaredNorm();
            const double s = dd > 0 ? std::clamp((x - points[i - 1]).dot(d) / dd, 0.0, 1.0) : 0.0;
            const double dist = (points[i - 1] + s * d - x).squaredNorm();
            if (dist < best) {
                best = dist;
                t = arc[i - 1] + s * (arc[i] - arc[i - 1]);
            }
        }
        return t;
    }
    Vec3 at(double t) const
    {
        const std::size_t i =
            static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), t) - arc.begin());
        if (i == 0)
            return points.front();
        if (i >= points.size())
            return points.back();
        const double span = arc[i] - arc[i - 1];
        const double s = span > 0 ? (t - arc[i - 1]) / span : 0.0;
        return points[i - 1] + s * (points[i] - points[i - 1]);
    }
};

std::vector<Vec3> positionsOf(const Model &m, const std::vector<int> &vertices)
{
    std::vector<Vec3> p;
    for (int v : vertices)
        p.push_back(m.vertices[v]);
    return p;
}

// The merged polyline: chain[0] and chain.back() are the two ends (each the pair of line ends and
// the short lines between them); the interior vertices of both lines are in between, in order.
struct MergedLines {
    std::vector<Vec3> chain;
    std::vector<int> chainOfA, chainOfB; // line vertex → chain index
    std::unordered_map<int, int> endOf;  // global vertex of an end → chain index (0 or last)
};

// Interior entries are ordered by their parameter along A (B's made monotone); each gets the
// point between A and B at its parameters on both (also made monotone), `shareA` of the way from B
// to A (1: on A). B is reversed in place when it runs the other way.
MergedLines mergeLines(const Model &m, const std::vector<int> &a, std::vector<int> &b,
                       double shareA)
{
    auto between = [shareA](const Vec3 &onA, const Vec3 &onB) {
        return shareA * onA + (1.0 - shareA) * onB;
    };
    const Polyline pa(positionsOf(m, a));
    if ((m.vertices[b.front()] - m.vertices[a.front()]).norm()
            + (m.vertices[b.back()] - m.vertices[a.back()]).norm()
        > (m.vertices[b.back()] - m.vertices[a.front()]).norm()
              + (m.vertices[b.front()] - m.vertices[a.back()]).norm())
        std::reverse(b.begin(), b.end());
    const Polyline pb(positionsOf(m, b));
    struct Entry {
        double t, u;
        bool onB;
        int index;
    };
    std::vector<Entry> entries;
    for (std::size_t k = 1; k + 1 < a.size(); ++k)
        entries.push_back({pa.arc[k], pb.project(pa.points[k]), false, static_cast<int>(k)});
    double tMax = 0.0;
    for (std::size_t j = 1; j + 1 < b.size(); ++j) {
        tMax = std::max(tMax, pa.project(pb.points[j]));
        entries.push_back({tMax, pb.arc[j], true, static_cast<int>(j)});
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry &x, const Entry &y) {
        return x.t < y.t || (x.t == y.t && !x.onB && y.onB);
    });
    MergedLines merged;
    merged.chainOfA.assign(a.size(), -1);
    merged.chainOfB.assign(b.size(), -1);
    merged.chain.push_back(between(pa.points.front(), pb.points.front()));
    merged.chainOfA.front() = merged.chainOfB.front() = 0;
    // Vertices of A and B facing each other exactly (regular grids) become one chain entry.
    const double same = 1e-12 * (pa.length() + pb.length());
    auto append = [&](const Vec3 &p) {
        if ((p - merged.chain.back()).norm() > same)
            merged.chain.push_back(p);
        return static_cast<int>(merged.chain.size()) - 1;
    };
    double uMax = 0.0;
    for (const Entry &e : entries) {
        uMax = std::max(uMax, e.u);
        (e.onB ? merged.chainOfB : merged.chainOfA)[e.index] =
            append(between(pa.at(e.t), pb.at(uMax)));
    }
    merged.chainOfA.back() = merged.chainOfB.back() =
        append(between(pa.points.back(), pb.points.back()));
    merged.endOf[a.front()] = merged.endOf[b.front()] = 0;
    merged.endOf[a.back()] = merged.endOf[b.back()] = merged.chainOfA.back();
    return merged;
}

// The triangles of a surface around the ends of a strip, once each end has shrunk to a point,
// are replaced by a triangulation of the polygon around them (ear clipping in their mean plane,
// with the chain vertices inserted along the lines): moving the ends alone would fold the long
// thin triangles boxes often have there.
template <class Inserted, class ChainVertex, class IsChain>
bool refillStar(const Surface &in, const std::vector<int> &global,
                const std::vector<Triangle> &star, const std::vector<int> &local,
                const Inserted &inserted, const ChainVertex &chainVertex, const IsChain &isChain,
                Surface &surface, std::vector<Vec3> &before)
{
    Vec3 normal = Vec3::Zero();
    std::map<std::pair<int, int>, int> edges; // directed boundary edges (local ids) with counts
    for (const Triangle &t : star) {
        normal +=
            (in.vertices[t[1]] - in.vertices[t[0]]).cross(in.vertices[t[2]] - in.vertices[t[0]]);
        for (int e = 0; e < 3; ++e) {
            std::vector<int> path{local[t[e]]};
            for (int c : inserted(global[t[e]], global[t[(e + 1) % 3]]))
                path.push_back(chainVertex(c));
            path.push_back(local[t[(e + 1) % 3]]);
            for (std::size_t k = 0; k + 1 < path.size(); ++k) {
                if (path[k] == path[k + 1])
                    continue;
                auto reverse = edges.find({path[k + 1], path[k]});
                if (reverse != edges.end()) {
                    if (--reverse->second == 0)
                        edges.erase(reverse);
                } else {
                    ++edges[{path[k], path[k + 1]}];
                }
            }
        }
    }
    if (normal.isZero())
        return false;
    std::map<int, int> next;
    for (const auto &[edge, count] : edges) {
        if (count != 1 || !next.emplace(edge.first, edge.second).second)
            return false; // not one simple loop
    }
    std::vector<std::vector<int>> loops; // one per end the surface touches
    while (!next.empty()) {
        std::vector<int> loop{next.begin()->first};
        for (;;) {
            auto it = next.find(loop.back());
            if (it == next.end())
                return false; // open: not a polygon
            const int n = it->second;
            next.erase(it);
            if (n == loop.front())
                break;
            loop.push_back(n);
        }
        if (loop.size() < 3)
            return false;
        loops.push_back(std::move(loop));
    }
    normal.normalize();
    const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
    auto flat = [&](int id) {
        return Eigen::Vector2d(surface.vertices[id].dot(u), surface.vertices[id].dot(v));
    };
    auto cross2 = [](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
        return a.x() * b.y() - a.y() * b.x();
    };
    for (std::vector<int> &loop : loops) {
        while (loop.size() > 3) {
            // The ear with the largest smallest angle: along the merged line the loop has runs
            // of nearly aligned vertices, whose ears are slivers.
            double best = 0.0;
            std::size_t chosen = loop.size();
            const auto offLine =
                std::count_if(loop.begin(), loop.end(), [&](int id) { return !isChain(id); });
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const int p = loop[(i + loop.size() - 1) % loop.size()], c = loop[i],
                          n = loop[(i + 1) % loop.size()];
                const Eigen::Vector2d a = flat(p), b = flat(c), d = flat(n);
                if (!(cross2(b - a, d - b) > 0))
                    continue;
                bool empty = true;
                for (int w : loop) {
                    if (w == p || w == c || w == n)
                        continue;
                    const Eigen::Vector2d x = flat(w);
                    if (cross2(b - a, x - a) > 0 && cross2(d - b, x - b) > 0
                        && cross2(a - d, x - d) > 0)
                        empty = false;
                }
                // An ear with its three corners on the merged line would lie on it, and the
                // surface across the line may make the same one: a last resort only.
                // Clipping the last vertex off the line would leave only such ears.
                const bool onLine =
                    (isChain(p) && isChain(c) && isChain(n)) || (!isChain(c) && offLine == 1);
                const double quality = triangleMinAngleDeg(surface.vertices[p], surface.vertices[c],
                                                           surface.vertices[n])
                                       * (onLine ? 1e-6 : 1.0);
                if (empty && quality > best) {
                    best = quality;
                    chosen = i;
                }
            }
            if (chosen == loop.size())
                return false;
            const std::size_t i = chosen;
            surface.triangles.push_back(
                {loop[(i + loop.size() - 1) % loop.size()], loop[i], loop[(i + 1) % loop.size()]});
            before.push_back(normal);
            loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
        }
        surface.triangles.push_back({loop[0], loop[1], loop[2]});
        before.push_back(normal);
    }
    return true;
}

// Input slivers with three corners on a line (a kink of it) are no longer flat once the line has
// moved, and can cut the surfaces across it: each is dropped and the edge it closed split at its
// middle corner, as line_fins.h does in the output.
template <class IsChain>
void unfoldAlongLine(Surface &surface, std::vector<Vec3> &before, const IsChain &isChain)
{
    for (int pass = 0; pass < 4; ++pass) {
        std::map<std::pair<int, int>, int> directed;
        for (std::size_t k = 0; k < surface.triangles.size(); ++k)
            for (int e = 0; e < 3; ++e)
                directed[{surface.triangles[k][e], surface.triangles[k][(e + 1) % 3]}] =
                    static_cast<int>(k);
        std::vector<char> dead(surface.triangles.size(), 0);
        std::vector<Triangle> added;
        std::vector<Vec3> addedBefore;
        for (std::size_t k = 0; k < surface.triangles.size(); ++k) {
            const Triangle t = surface.triangles[k];
            if (dead[k] || !isChain(t[0]) || !isChain(t[1]) || !isChain(t[2]))
                continue;
            const std::array<double, 3> angles =
                triangleShape(surface.vertices[t[0]], surface.vertices[t[1]],
                              surface.vertices[t[2]])
                    .anglesDeg;
            const auto mid = std::max_element(angles.begin(), angles.end()) - angles.begin();
            const int m = t[mid], p = t[(mid + 1) % 3], q = t[(mid + 2) % 3];
            auto across = directed.find({q, p});
            if (across == directed.end() || dead[across->second])
                continue;
            const Triangle other = surface.triangles[across->second];
            int x = -1;
            for (int v : other)
                if (v != p && v != q)
                    x = v;
            if (x == m || isChain(x) || directed.count({m, x}) || directed.count({x, m}))
                continue;
            dead[k] = dead[across->second] = 1;
            added.push_back({q, m, x});
            added.push_back({m, p, x});
            addedBefore.insert(addedBefore.end(), 2, before[across->second]);
        }
        if (added.empty())
            return;
        std::vector<Triangle> kept;
        std::vector<Vec3> keptBefore;
        for (std::size_t k = 0; k < surface.triangles.size(); ++k)
            if (!dead[k]) {
                kept.push_back(surface.triangles[k]);
                keptBefore.push_back(before[k]);
            }
        kept.insert(kept.end(), added.begin(), added.end());
        keptBefore.insert(keptBefore.end(), addedBefore.begin(), addedBefore.end());
        surface.triangles = std::move(kept);
        before = std::move(keptBefore);
    }
}

// Collapses one strip of `m`; false (m unchanged) when it cannot be done cleanly.
bool collapseStrip(Model &m, const ThinStrip &strip, double shareA)
{
    const Line &lineA = m.lines[strip.lines[0]], &lineB = m.lines[strip.lines[1]];
    const std::vector<int> a = lineA.vertices;
    std::vector<int> b = lineB.vertices; // in A's direction after mergeLines
    if (a.size() < 2 || b.size() < 2 || a.front() == a.back() || b.front() == b.back())
        return false;
    for (int s : lineA.surfaces)
        if (s != strip.surface
            && std::binary_search(lineB.surfaces.begin(), lineB.surfaces.end(), s))
            return false; // the merged line would join that surface to itself
    MergedLines merged = mergeLines(m, a, b, shareA);
    for (int l : m.surfaces[strip.surface].lines) {
        if (l == strip.lines[0] || l == strip.lines[1])
            continue;
        const Line &end = m.lines[l];
        int at = -1;
        for (int v : {end.vertices.front(), end.vertices.back()})
            if (auto it = merged.endOf.find(v); it != merged.endOf.end() && at < 0)
                at = it->second;
        if (at < 0)
            return false; // not an end between the two lines
        for (int v : end.vertices)
            merged.endOf[v] = at;
    }
    std::unordered_map<int, int> indexA, indexB; // global vertex → index on the line
    for (std::size_t k = 0; k < a.size(); ++k)
        indexA[a[k]] = static_cast<int>(k);
    for (std::size_t j = 0; j < b.size(); ++j)
        indexB[b[j]] = static_cast<int>(j);
    auto chainOf = [&](int g) {
        if (auto it = merged.endOf.find(g); it != merged.endOf.end())
            return it->second;
        if (auto it = indexA.find(g); it != indexA.end())
            return merged.chainOfA[it->second];
        if (auto it = indexB.find(g); it != indexB.end())
            return merged.chainOfB[it->second];
        return -1;
    };
    // Chain entries strictly between the two ends of an edge of A or B, in the edge's direction.
    auto inserted = [&](int g0, int g1) {
        std::vector<int> between;
        for (const auto *index : {&indexA, &indexB}) {
            auto i0 = index->find(g0), i1 = index->find(g1);
            if (i0 == index->end() || i1 == index->end() || std::abs(i0->second - i1->second) != 1)
                continue;
            const int c0 = chainOf(g0), c1 = chainOf(g1);
            for (int c = std::min(c0, c1) + 1; c < std::max(c0, c1); ++c)
                between.push_back(c);
            if (c0 > c1)
                std::reverse(between.begin(), between.end());
            return between;
        }
        return between;
    };

    Model out = m;
    out.surfaces.clear();
    std::vector<int> newId(m.surfaces.size(), -1);
    for (int s = 0; s < static_cast<int>(m.surfaces.size()); ++s) {
        if (s == strip.surface)
            continue;
        const Surface &in = m.surfaces[s];
        const std::vector<int> &global = m.surfaceVertexToGlobal[s];
        Surface surface = in;
        surface.vertices.clear();
        surface.triangles.clear();
        // Local vertices: the surface's own, but one per chain entry (the ends shrink to one).
        std::vector<int> local(in.vertices.size(), -1);
        std::unordered_map<int, int> chainLocal;
        std::vector<char> onChain; // by local vertex
        auto chainVertex = [&](int c) {
            auto [it, added] = chainLocal.emplace(c, static_cast<int>(surface.vertices.size()));
            if (added) {
                surface.vertices.push_back(merged.chain[c]);
                onChain.resize(surface.vertices.size(), 0);
                onChain.back() = 1;
            }
            return it->second;
        };
        for (std::size_t v = 0; v < in.vertices.size(); ++v) {
            const int c = chainOf(global[v]);
            if (c >= 0) {
                local[v] = chainVertex(c);
            } else {
                local[v] = static_cast<int>(surface.vertices.size());
                surface.vertices.push_back(in.vertices[v]);
            }
        }
        auto isChain = [&](int id) { return id < static_cast<int>(onChain.size()) && onChain[id]; };
        std::vector<Vec3> vertexNormals(in.vertices.size(), Vec3::Zero()); // area-weighted
        for (const Triangle &t : in.triangles) {
            const Vec3 n = (in.vertices[t[1]] - in.vertices[t[0]])
                               .cross(in.vertices[t[2]] - in.vertices[t[0]]);
            for (int v : t)
                vertexNormals[v] += n;
        }
        std::vector<Vec3> before; // the surface's normal where each output triangle comes from
        const int last = static_cast<int>(merged.chain.size()) - 1;
        std::vector<Triangle> star; // triangles around an end: filled again once the end is a point
        for (const Triangle &t : in.triangles) {
            bool atEnd = false;
            for (int k = 0; k < 3; ++k) {
                const int c = chainOf(global[t[k]]);
                atEnd = atEnd || c == 0 || c == last;
            }
            if (atEnd) {
                star.push_back(t);
                continue;
            }
            // The surface's way round here: input slivers along lines are sometimes turned over
            // (their own normal says nothing), the area around their corners is not.
            const Vec3 normal = vertexNormals[t[0]] + vertexNormals[t[1]] + vertexNormals[t[2]];
            int split = -1;
            std::vector<int> between;
            for (int e = 0; e < 3; ++e) {
                std::vector<int> ins = inserted(global[t[e]], global[t[(e + 1) % 3]]);
                if (ins.empty())
                    continue;
                if (split >= 0)
                    split = 3; // two edges on the lines (a sliver along them): refilled alone
                else
                    split = e;
                between = std::move(ins);
            }
            if (split == 3) {
                if (!refillStar(in, global, {t}, local, inserted, chainVertex, isChain, surface,
                                before))
                    return false;
                continue;
            }
            const Triangle lt{local[t[0]], local[t[1]], local[t[2]]};
            if (split < 0) {
                if (lt[0] != lt[1] && lt[1] != lt[2] && lt[0] != lt[2]) {
                    surface.triangles.push_back(lt);
                    // A triangle off the lines does not move, so it cannot fold; its own normal
                    // may disagree with its corners' (modelA5's h1 has one at cos −0.375 that
                    // kept its 18 m strip f3_1 and 62 triangles under 30°).
                    const bool moves = isChain(lt[0]) || isChain(lt[1]) || isChain(lt[2]);
                    before.push_back(moves ? normal : Vec3::Zero());
                }
                continue;
            }
            // A fan from the opposite vertex over the split edge keeps the orientation.
            const int apex = lt[(split + 2) % 3];
            int from = lt[split];
            for (int c : between) {
                const int to = chainVertex(c);
                surface.triangles.push_back({from, to, apex});
                before.push_back(normal);
                from = to;
            }
            surface.triangles.push_back({from, lt[(split + 1) % 3], apex});
            before.push_back(normal);
        }
        if (!star.empty()
            && !refillStar(in, global, star, local, inserted, chainVertex, isChain, surface,
                           before))
            return false;
        unfoldAlongLine(surface, before, isChain);
        for (std::size_t k = 0; k < surface.triangles.size(); ++k) {
            const Triangle &t = surface.triangles[k];
            const Vec3 n = (surface.vertices[t[1]] - surface.vertices[t[0]])
                               .cross(surface.vertices[t[2]] - surface.vertices[t[0]]);
            // Slivers along the line (three corners on it) were flat before and stay so.
            const bool alongLine = isChain(t[0]) && isChain(t[1]) && isChain(t[2]);
            if (!alongLine && !before[k].isZero() && !(n.dot(before[k]) > 0.0))
                return false; // folded or flat: keep the strip rather than break the surface
        }
        // Drop the local vertices no triangle uses any more (the ends that shrank).
        std::vector<int> used(surface.vertices.size(), -1);
        std::vector<Vec3> kept;
        for (Triangle &t : surface.triangles)
            for (int &v : t) {
                if (used[v] < 0) {
                    used[v] = static_cast<int>(kept.size());
                    kept.push_back(surface.vertices[v]);
                }
                v = used[v];
            }
        surface.vertices = std::move(kept);
        if (surface.triangles.empty())
            return false;
        newId[s] = static_cast<int>(out.surfaces.size());
        out.surfaces.push_back(std::move(surface));
    }
    auto renumber = [&](std::vector<RegionSide> &sides) {
        std::vector<RegionSide> kept;
        for (RegionSide side : sides)
            if (newId[side.surface] >= 0) {
                side.surface = newId[side.surface];
                kept.push_back(side);
            }
        sides = std::move(kept);
    };
    for (Region &r : out.regions)
        renumber(r.boundaries);
    renumber(out.universe);
    m = recoverTopology(std::move(out));
    return true;
}

} // namespace

StripCollapse removeThinStrips(const Model &input, double maxWidth, SimplificationLedger &ledger,
                               Progress &progress)
{
    StripCollapse result;
    result.model = input;
    result.surfaceToInput.resize(input.surfaces.size());
    for (std::size_t s = 0; s < input.surfaces.size(); ++s)
        result.surfaceToInput[s] = static_cast<int>(s);
    std::vector<char> refused(input.surfaces.size(), 0);        // by input surface
    std::optional<std::map<std::string, std::size_t>> problems; // validity counts of result.model
    for (;;) {
        progress.tick(0.0, "thin strips");
        const std::vector<ThinStrip> strips = findThinStrips(result.model, maxWidth);
        auto next = std::find_if(strips.begin(), strips.end(), [&](const ThinStrip &s) {
            return !refused[result.surfaceToInput[s.surface]];
        });
        if (next == strips.end())
            return result;
        const ThinStrip strip = *next;
        const int inputSurface = result.surfaceToInput[strip.surface];
        // Half-way first; where that folds a neighbour's triangle or adds a problem (input
        // slivers along a cutoff narrower than half the strip: modelA5's f3_1, 18 m wide), onto
        // either line instead, for a strip at most half the limit wide: no line then moves
        // farther than half-way merging may move it.
        Model model;
        bool done = false;
        double share = 0.5;
        for (double shareA : {0.5, 1.0, 0.0}) {
            if (shareA != 0.5 && strip.width > 0.5 * maxWidth)
                break;
            progress.tick(0.0, "thin strips"); // each try is a validity check
            share = shareA;
            model = result.model;
            if (!collapseStrip(model, strip, shareA))
                continue;
            // Exact checks decide, not the construction: a removal that adds any problem (two
            // surfaces crossing where a line was bent, say) is undone.
            // The checks tick inside: two of them on modelA5 took 0.4 s between ticks on a
            // loaded machine.
            Progress check(progress, 0.0, 0.0, "thin strips");
            if (!problems)
                problems = checkValidity(result.model, check).counts;
            const std::map<std::string, std::size_t> after = checkValidity(model, check).counts;
            const bool worse = std::any_of(after.begin(), after.end(), [&](const auto &check) {
                auto before = problems->find(check.first);
                return check.second > (before == problems->end() ? 0 : before->second);
            });
            if (!worse) {
                problems = after;
                done = true;
                break;
            }
        }
        if (!done) {
            refused[inputSurface] = 1;
            continue;
        }
        const Surface &gone = result.model.surfaces[strip.surface];
        double area = 0.0;
        Vec3 centre = Vec3::Zero();
        for (const Triangle &t : gone.triangles) {
            const double ta =
                triangleArea(gone.vertices[t[0]], gone.vertices[t[1]], gone.vertices[t[2]]);
            area += ta;
            centre += ta * (gone.vertices[t[0]] + gone.vertices[t[1]] + gone.vertices[t[2]]) / 3.0;
        }
        if (area > 0.0)
            centre /= area;
        // The strip, its width and the limit it was under, in the notes' %1, %2, %3.
        const std::vector<std::string> strip3{gone.name,
                                              std::to_string(static_cast<int>(strip.width + 0.5)),
                                              std::to_string(static_cast<int>(maxWidth + 0.5))};
        LedgerRecord merge;
        merge.kind = LedgerKind::CloseFeatureMerge;
        // The lines are named as in the input: a later strip's lines exist only in the model
        // with the earlier strips removed, the input surface's two longest lines are the same.
        merge.inputs = {surfaceRef(input, inputSurface)};
        std::vector<int> inputLines;
        for (const auto &[length, l] : boundaryLinesByLength(input, inputSurface))
            if (inputLines.size() < 2)
                inputLines.push_back(l);
        std::sort(inputLines.begin(), inputLines.end());
        for (int l : inputLines)
            merge.inputs.push_back(lineRef(input, l));
        merge.position = centre;
        merge.size = strip.width;
        merge.sizeMeaning = "distance";
        if (share == 0.5)
            setNote(merge, {QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "strip %1 (%2 m wide, limit %3 m) removed: its two "
                                              "lines merged half-way (Fig 4.7 per strip)"),
                            strip3});
        else
            setNote(merge, {QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "strip %1 (%2 m wide, limit %3 m) removed: its two "
                                              "lines merged onto one of them (Fig 4.7 per strip)"),
                            strip3});
        ledger.push_back(merge);
        LedgerRecord lost;
        lost.kind = LedgerKind::SurfaceLost;
        lost.inputs = {surfaceRef(input, inputSurface)};
        lost.position = centre;
        lost.size = area;
        lost.sizeMeaning = "area";
        setNote(lost,
                {QT_TRANSLATE_NOOP("stratamesh::Core",
                                   "strip %1 (%2 m wide, limit %3 m) removed before remeshing"),
                 strip3});
        ledger.push_back(lost);
        ThinStrip recorded = strip;
        recorded.surface = inputSurface;
        result.removed.push_back(recorded);
        result.surfaceToInput.erase(result.surfaceToInput.begin() + strip.surface);
        result.model = std::move(model);
    }
}

} // namespace stratamesh
