#include "remesh/mesh_smoothing.h"

#include "quality/triangle_quality.h"
#include "remesh/intersection_repair.h"

#include <algorithm>
#include <limits>
#include <map>
#include <vector>

namespace stratamesh {

namespace {

double worstQualityAround(const EditableSoup &soup, int v, const Vec3 &at)
{
    double worst = std::numeric_limits<double>::max();
    for (int t : soup.vertexTriangles(v)) {
        const auto &tv = soup.triangle(t).v;
        std::array<Vec3, 3> p;
        for (int k = 0; k < 3; ++k)
            p[k] = tv[k] == v ? at : soup.position(tv[k]);
        worst = std::min(worst, triangleQuality(p[0], p[1], p[2]));
    }
    return worst;
}

// What relaxation needs of a vertex's neighbourhood. Moves never change the connectivity, so it
// is gathered once rather than at every pass (the class alone walks the whole fan).
struct RelaxedVertex {
    int v = -1;
    VertexClass kind = VertexClass::Fixed;
    std::vector<int> neighbours; // Interior: the ring; Line: the two neighbours along the line
};

std::vector<RelaxedVertex> relaxedVertices(const EditableSoup &soup, bool lines)
{
    std::vector<RelaxedVertex> out;
    for (int v = 0; v < soup.pointCount(); ++v) {
        if (soup.vertexTriangles(v).empty())
            continue;
        RelaxedVertex r;
        r.v = v;
        r.kind = soup.vertexClass(v);
        if (r.kind == VertexClass::Interior) {
            r.neighbours = soup.neighbours(v);
        } else if (r.kind == VertexClass::Line && lines && !soup.point(v).lines.empty()) {
            for (int w : soup.neighbours(v))
                if (soup.isFeatureEdge(v, w))
                    r.neighbours.push_back(w);
            if (r.neighbours.size() != 2)
                continue;
        } else {
            continue;
        }
        out.push_back(std::move(r));
    }
    return out;
}

} // namespace

int relaxVertices(EditableSoup &soup, InputProjector &projector, const SmoothingParams &params,
                  Progress &progress)
{
    // Rings already this good after the plain move are left to it (most of them: the search
    // costs a projection per candidate).
    constexpr double kSearchBelow = 0.7;
    int moves = 0;
    std::map<int, Vec3> start; // moved vertices → where the dual put them
    const std::vector<RelaxedVertex> vertices = relaxedVertices(soup, params.lines);
    for (int pass = 0; pass < params.passes; ++pass) {
        int passMoves = 0;
        progress.tick(0.7 * pass / params.passes, "pass " + std::to_string(pass + 1));
        std::size_t done = 0;
        for (const RelaxedVertex &r : vertices) {
            // A pass over modelA5 at 5000 sites takes about 0.1 s on a loaded machine.
            if (++done % 512 == 0)
                progress.tick(0.7 * (pass + static_cast<double>(done) / vertices.size())
                                  / params.passes,
                              "pass " + std::to_string(pass + 1));
            const int v = r.v;
            const VertexClass c = r.kind;
            const Vec3 old = soup.position(v);
            Vec3 target;
            if (c == VertexClass::Interior) {
                Vec3 sum = Vec3::Zero();
                for (int w : r.neighbours)
                    sum += soup.position(w);
                const int surface = soup.triangle(soup.vertexTriangles(v).front()).surface;
                target = projector.onSurface(surface,
                                             sum / static_cast<double>(r.neighbours.size()), old);
                // The centroid evens the ring; next to a thin piece or a line a step towards one
                // neighbour may open the worst angle more: the best worst quality wins.
                double best = worstQualityAround(soup, v, target);
                if (best < kSearchBelow)
                    for (int w : r.neighbours) {
                        const Vec3 candidate = projector.onSurface(
                            surface, old + 0.25 * (soup.position(w) - old), old);
                        const double q = worstQualityAround(soup, v, candidate);
                        if (q > best) {
                            best = q;
                            target = candidate;
                        }
                    }
            } else {
                // The middle of the two line neighbours evens the spacing along the line, but a
                // thin piece beside it needs its two sides staggered: slides along the line
                // towards either neighbour compete, and the best worst quality wins.
                const std::vector<int> &along = r.neighbours;
                const std::vector<int> &lines = soup.point(v).lines;
                target = projector.onLines(
                    lines, (soup.position(along[0]) + soup.position(along[1])) / 2.0);
                double best = worstQualityAround(soup, v, target);
                if (best < kSearchBelow)
                    for (int w : along)
                        for (double f : {0.2, 0.4}) {
                            const Vec3 candidate =
                                projector.onLines(lines, old + f * (soup.position(w) - old));
                            const double q = worstQualityAround(soup, v, candidate);
                            if (q > best) {
                                best = q;
                                target = candidate;
                            }
                        }
            }
            const double before = worstQualityAround(soup, v, old);
            for (double f : {1.0, 0.5}) {
                // Half-way is put back on the input too: across a bend of the line (or of the
                // surface) the straight middle is off it.
                Vec3 candidate = target;
                if (f != 1.0)
                    candidate =
                        c == VertexClass::Interior
                            ? projector.onSurface(
                                soup.triangle(soup.vertexTriangles(v).front()).surface,
                                old + f * (target - old), old)
                            : projector.onLines(soup.point(v).lines, old + f * (target - old));
                if (worstQualityAround(soup, v, candidate) < before)
                    continue;
                if (soup.tryMove(v, candidate, 0.0)) {
                    start.emplace(v, old);
                    ++passMoves;
                    break;
                }
            }
        }
        moves += passMoves;
        if (passMoves == 0)
            break;
    }
    // The checks above are local to each vertex's triangles; a move can still push a triangle
    // through another surface nearby. Moved vertices of intersecting triangles go back.
    for (int round = 0; round < 3 && !start.empty(); ++round) {
        progress.tick(0.7 + 0.1 * round, "moves undone");
        int restored = 0;
        for (const auto &[a, b] : soupIntersections(soup))
            for (int t : {a, b})
                for (int v : soup.triangle(t).v) {
                    auto it = start.find(v);
                    if (it != start.end() && soup.tryMove(v, it->second, 0.0)) {
                        start.erase(it);
                        ++restored;
                    }
                }
        if (restored == 0)
            break;
    }
    return moves;
}

} // namespace stratamesh
