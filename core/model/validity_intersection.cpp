// surface_intersection: triangles may meet only along the vertices and edge they share (thesis
// §3.2). Candidate pairs come from CGAL's box intersection; each pair is decided with exact
// predicates on the stored doubles. With exact vertex merging, two triangles share a point only
// through a shared global vertex, which gives the three cases below.
#include "common/translate_noop.h"
#include "model/shared_edge_overlap.h"
#include "model/validity_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <optional>

namespace stratamesh::validity_detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Tri = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

struct Face {
    std::array<int, 3> v; // global vertex ids
    int surface;
    int triangle;
};

Point toPoint(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

// Where segment [a, b] meets triangle t, in doubles, for the report only (no decision rests
// on it). CGAL 5.5's triangle–triangle intersection construction can raise SIGFPE (GMP given a
// NaN) when an edge of one triangle lies in the other's plane, as on remeshed box faces.
std::optional<Vec3> segmentCrossing(const Vec3 &a, const Vec3 &b, const std::array<Vec3, 3> &t)
{
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    const double da = n.dot(a - t[0]), db = n.dot(b - t[0]);
    Vec3 candidates[3];
    int count = 0;
    if (da == 0.0)
        candidates[count++] = a;
    if (db == 0.0)
        candidates[count++] = b;
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
        candidates[count++] = a + da / (da - db) * (b - a);
    const double slack = 1e-9 * n.squaredNorm();
    for (int c = 0; c < count; ++c) {
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k)
            inside = (t[(k + 1) % 3] - t[k]).cross(candidates[c] - t[k]).dot(n) >= -slack;
        if (inside)
            return candidates[c];
    }
    return std::nullopt;
}

class PairTester {
public:
    explicit PairTester(const Model &model) : m_model(model) {}

    // Where the two faces meet outside what they share, or nothing when they do not.
    std::optional<Vec3> test(const Face &f, const Face &g, bool wantPosition) const
    {
        int sharedF[3], sharedG[3], n = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (f.v[i] == g.v[j]) {
                    sharedF[n] = i;
                    sharedG[n] = j;
                    ++n;
                }
        if (n == 3)
            return std::nullopt; // a duplicate triangle, reported by duplicate_triangle
        const Tri tf = triangle(f), tg = triangle(g);
        if (n == 0) {
            if (!CGAL::do_intersect(tf, tg))
                return std::nullopt;
            return wantPosition ? meetingPoint(f, g, {0, 1, 2}, {0, 1, 2}) : Vec3::Zero();
        }
        if (n == 1) {
            // Sharing vertex p, T1 ∩ T2 ≠ {p} exactly when the edge of one opposite p meets the
            // other: along any direction leaving p inside both, the nearer opposite edge is reached
            // inside the other triangle (convexity), coplanar or not.
            const Segment sf(point(f.v[(sharedF[0] + 1) % 3]), point(f.v[(sharedF[0] + 2) % 3]));
            const Segment sg(point(g.v[(sharedG[0] + 1) % 3]), point(g.v[(sharedG[0] + 2) % 3]));
            if (CGAL::do_intersect(sf, tg) || CGAL::do_intersect(sg, tf))
                return wantPosition
                           ? meetingPoint(f, g, {(sharedF[0] + 1) % 3}, {(sharedG[0] + 1) % 3})
                           : Vec3::Zero();
            return std::nullopt;
        }
        // Sharing edge uv: if the opposite corners a, b are off each other's plane the triangles
        // meet along uv only; coplanar, they overlap when a and b are on the same side of uv.
        const int a = f.v[3 - sharedF[0] - sharedF[1]];
        const int b = g.v[3 - sharedG[0] - sharedG[1]];
        const auto &x = m_model.vertices;
        if (!sharedEdgeTrianglesOverlap(x[f.v[sharedF[0]]], x[f.v[sharedF[1]]], x[a], x[b]))
            return std::nullopt;
        return centre(f, g);
    }

    Tri triangle(const Face &f) const { return {point(f.v[0]), point(f.v[1]), point(f.v[2])}; }

private:
    Point point(int v) const { return toPoint(m_model.vertices[v]); }
    // A point where the edges starting at the given corners of one face cross the other face;
    // the centre of both when rounding hides every crossing.
    Vec3 meetingPoint(const Face &f, const Face &g, std::initializer_list<int> edgesF,
                      std::initializer_list<int> edgesG) const
    {
        const auto &x = m_model.vertices;
        const std::array<Vec3, 3> pf{x[f.v[0]], x[f.v[1]], x[f.v[2]]},
            pg{x[g.v[0]], x[g.v[1]], x[g.v[2]]};
        for (int k : edgesF)
            if (const auto p = segmentCrossing(pf[k], pf[(k + 1) % 3], pg))
                return *p;
        for (int k : edgesG)
            if (const auto p = segmentCrossing(pg[k], pg[(k + 1) % 3], pf))
                return *p;
        return centre(f, g);
    }
    Vec3 centre(const Face &f, const Face &g) const
    {
        Vec3 c = Vec3::Zero();
        for (int i = 0; i < 3; ++i)
            c += m_model.vertices[f.v[i]] + m_model.vertices[g.v[i]];
        return c / 6.0;
    }

    const Model &m_model;
};

// The faces the intersection test decides: degenerate ones are reported by degenerate_triangle
// and meaningless here.
std::optional<Face> checkedFace(const Model &model, int surface, int triangle)
{
    const std::vector<int> &g = model.surfaceVertexToGlobal[surface];
    const Triangle &t = model.surfaces[surface].triangles[triangle];
    const Face f{{g[t[0]], g[t[1]], g[t[2]]}, surface, triangle};
    if (f.v[0] == f.v[1] || f.v[1] == f.v[2] || f.v[0] == f.v[2])
        return std::nullopt;
    if (CGAL::collinear(toPoint(model.vertices[f.v[0]]), toPoint(model.vertices[f.v[1]]),
                        toPoint(model.vertices[f.v[2]])))
        return std::nullopt;
    return f;
}

std::vector<Face> checkedFaces(const Model &model)
{
    std::vector<Face> faces;
    faces.reserve(model.triangleCount());
    for (std::size_t si = 0; si < model.surfaces.size(); ++si)
        for (std::size_t ti = 0; ti < model.surfaces[si].triangles.size(); ++ti)
            if (const auto f = checkedFace(model, static_cast<int>(si), static_cast<int>(ti)))
                faces.push_back(*f);
    return faces;
}

} // namespace

void checkIntersections(const CheckInput &in, ProblemSink &sink, Progress &progress)
{
    const Model &model = in.model;
    const std::vector<Face> faces = checkedFaces(model);
    std::vector<Box> boxes;
    boxes.reserve(faces.size());
    const PairTester tester(model);
    for (std::size_t i = 0; i < faces.size(); ++i)
        boxes.emplace_back(tester.triangle(faces[i]).bbox(), static_cast<int>(i));

    // The box search hands out candidate pairs (adjacent triangles' boxes always overlap); they
    // are decided in parallel by chunks, then reported in the order found, each with where the
    // triangles meet while the report still lists problems, as a serial check would.
    std::vector<std::pair<int, int>> chunk;
    std::vector<char> meets;
    std::size_t pairs = 0;
    const auto decide = [&] {
        meets.assign(chunk.size(), 0);
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, chunk.size(), 1024),
            [&](const tbb::blocked_range<std::size_t> &r) {
                for (std::size_t c = r.begin(); c < r.end(); ++c)
                    meets[c] = tester.test(faces[chunk[c].first], faces[chunk[c].second], false)
                                   .has_value();
            });
        for (std::size_t c = 0; c < chunk.size(); ++c) {
            if (!meets[c])
                continue;
            const Face &f = faces[chunk[c].first], &g = faces[chunk[c].second];
            const bool list = !sink.full(validity_check::surfaceIntersection);
            const Vec3 where = list ? tester.test(f, g, true).value_or(Vec3::Zero()) : Vec3::Zero();
            const Surface &sf = model.surfaces[f.surface], &sg = model.surfaces[g.surface];
            std::vector<std::string> names{sf.name};
            if (f.surface != g.surface)
                names.push_back(sg.name);
            sink.add(
                validity_check::surfaceIntersection, names, where,
                {QT_TRANSLATE_NOOP("stratamesh::Core",
                                   "triangle %1 of %2 and triangle %3 of %4 intersect near %5"),
                 {std::to_string(f.triangle), sf.name, std::to_string(g.triangle), sg.name,
                  pointText(where)}});
        }
        chunk.clear();
    };
    constexpr std::size_t kChunk = 1 << 18; // bounds the memory on models of millions of triangles
    auto callback = [&](const Box &x, const Box &y) {
        if (++pairs % 65536 == 0)
            progress.tick(
                0.2 + 0.7 * std::min(1.0, static_cast<double>(pairs) / (20.0 * faces.size() + 1)),
                "validity: intersections");
        chunk.emplace_back(x.info(), y.info());
        if (chunk.size() == kChunk)
            decide();
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), callback);
    decide();
}

} // namespace stratamesh::validity_detail

namespace stratamesh {

bool trianglesMeetOthers(const Model &model, int surface, const std::vector<int> &triangles)
{
    using namespace validity_detail;
    const std::vector<Face> faces = checkedFaces(model);
    const PairTester tester(model);
    std::vector<Face> asked;
    for (int t : triangles)
        if (const auto f = checkedFace(model, surface, t))
            asked.push_back(*f);
    std::vector<Box> mine, all;
    for (std::size_t i = 0; i < asked.size(); ++i)
        mine.emplace_back(tester.triangle(asked[i]).bbox(), static_cast<int>(i));
    for (std::size_t i = 0; i < faces.size(); ++i)
        all.emplace_back(tester.triangle(faces[i]).bbox(), static_cast<int>(i));
    bool meets = false;
    CGAL::box_intersection_d(
        mine.begin(), mine.end(), all.begin(), all.end(), [&](const Box &x, const Box &y) {
            meets = meets || tester.test(asked[x.info()], faces[y.info()], false).has_value();
        });
    return meets;
}

} // namespace stratamesh
