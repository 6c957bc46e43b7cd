#include "bench_remesh.h"

#include "bench_cases.h"

#include "common/progress.h"
#include "io/model_reader.h"
#include "model/topology.h"
#include "model/validity.h"
#include "quality/hausdorff.h"
#include "quality/mesh_statistics.h"
#include "remesh/surface_remesher.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace stratamesh::bench {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

double since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Row {
    std::string name;
    double seconds = 0.0;
    MeshStatistics stats;
    double hausdorffPct = 0.0;
    bool valid = false;
    std::size_t notSealed = 0;     // contact/border pieces that touch no other surface
    std::size_t intersections = 0; // intersecting triangle pairs
};

// Each surface remeshed alone by CGAL; line edges (borders, contacts, internal lines) are
// constrained, and kept as they are when `protect` is set.
Model cgalRemesh(const Model &input, double edgeLength, bool protect)
{
    std::set<std::pair<int, int>> lineEdges;
    for (const Line &l : input.lines)
        for (std::size_t i = 0; i + 1 < l.vertices.size() + (l.closed ? 1 : 0); ++i) {
            int a = l.vertices[i], b = l.vertices[(i + 1) % l.vertices.size()];
            lineEdges.insert({std::min(a, b), std::max(a, b)});
        }
    Model out = input;
    out.vertices.clear();
    out.surfaceVertexToGlobal.clear();
    out.lines.clear();
    out.corners.clear();
    for (std::size_t s = 0; s < input.surfaces.size(); ++s) {
        const Surface &in = input.surfaces[s];
        Mesh mesh;
        std::vector<Mesh::Vertex_index> vi;
        for (const Vec3 &p : in.vertices)
            vi.push_back(mesh.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
        for (const Triangle &t : in.triangles)
            mesh.add_face(vi[t[0]], vi[t[1]], vi[t[2]]);
        auto constrained =
            mesh.add_property_map<Mesh::Edge_index, bool>("e:constrained", false).first;
        for (Mesh::Edge_index e : mesh.edges()) {
            const int a = input.surfaceVertexToGlobal[s][mesh.vertex(e, 0)];
            const int b = input.surfaceVertexToGlobal[s][mesh.vertex(e, 1)];
            constrained[e] =
                mesh.is_border(e) || lineEdges.count({std::min(a, b), std::max(a, b)}) > 0;
        }
        PMP::isotropic_remeshing(faces(mesh), edgeLength, mesh,
                                 CGAL::parameters::number_of_iterations(3)
                                     .edge_is_constrained_map(constrained)
                                     .protect_constraints(protect));
        mesh.collect_garbage();
        Surface &o = out.surfaces[s];
        o.vertices.clear();
        o.triangles.clear();
        for (Mesh::Vertex_index v : mesh.vertices()) {
            const K::Point_3 &p = mesh.point(v);
            o.vertices.push_back(Vec3(p.x(), p.y(), p.z()));
        }
        for (Mesh::Face_index f : mesh.faces()) {
            Triangle t;
            int k = 0;
            for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
                t[k++] = static_cast<int>(v);
            o.triangles.push_back(t);
        }
    }
    return recoverTopology(out);
}

Row measure(const std::string &name, const Model &input, const Model &output, double seconds)
{
    Row r;
    r.name = name;
    r.seconds = seconds;
    r.stats = computeMeshStatistics(output);
    r.hausdorffPct = hausdorffDistance(input, output).symmetricPctBbox;
    const ValidityReport v = checkValidity(output);
    r.valid = v.valid;
    r.notSealed = v.count(validity_check::notSealed);
    r.intersections = v.count(validity_check::surfaceIntersection);
    return r;
}

// Wall time per stage of a run, from its progress reports: the time up to a report is the
// stage's that made it (stages report when a unit of work is done), named down to two levels
// ("Refinement round 2: Mesh building (2/3)"), CVT iterations as one.
class StageClock {
public:
    Progress::Callback callback()
    {
        m_last = std::chrono::steady_clock::now();
        return [this](double, const std::string &stage) {
            std::string name = stagePrefix(stage, kDepth);
            name = name.substr(0, name.find(" iteration ")); // CVT iterations: one stage
            auto found = std::find_if(m_stages.begin(), m_stages.end(),
                                      [&](const auto &s) { return s.first == name; });
            if (found == m_stages.end())
                found = m_stages.insert(m_stages.end(), {name, 0.0});
            found->second += since(m_last);
            m_last = std::chrono::steady_clock::now();
        };
    }
    // `total`: the run's own time, whose part after the last report no stage holds.
    void print(double total) const
    {
        double sum = 0.0;
        for (const auto &[name, seconds] : m_stages) {
            std::printf("      %-44s %6.2f s\n", name.c_str(), seconds);
            sum += seconds;
        }
        std::printf("      %-44s %6.2f s\n", "(after the last report)", total - sum);
    }

private:
    static constexpr int kDepth = 2;
    std::chrono::steady_clock::time_point m_last;
    std::vector<std::pair<std::string, double>> m_stages; // in order of first report
};

void print(const Row &r)
{
    std::printf("  %-34s %7.2f s %7zu V %7zu T  Q %.3f  <30° %5.2f %%  min %5.2f°  H %.3f %%  %s "
                "(not sealed %zu, "
                "intersections %zu)\n",
                r.name.c_str(), r.seconds, r.stats.vertices, r.stats.triangles, r.stats.meanQuality,
                r.stats.pctTrianglesAngleBelow30, r.stats.minAngleDeg, r.hausdorffPct,
                r.valid ? "valid" : "NOT valid", r.notSealed, r.intersections);
}

} // namespace

int runRemeshBench(const std::string &dataDir, int threads, int iterations, int repeat)
{
    try {
        std::unique_ptr<tbb::global_control> limit;
        if (threads > 0)
            limit = std::make_unique<tbb::global_control>(
                tbb::global_control::max_allowed_parallelism, threads);
        const Model input = recoverTopology(readModel(dataDir + "/modelA5.ml"));
        std::printf("remesh: modelA5, 5000 sites, %d iterations, %d threads\n", iterations,
                    threads > 0 ? threads : tbb::info::default_concurrency());
        print(measure("input", input, input, 0.0));

        RemeshParams params;
        params.sites = 5000;
        params.iterations = iterations;
        StageClock clock;
        Progress progress(clock.callback());
        const RemeshResult ours = remeshModel(input, params, progress);
        Row row = measure("ours (CVT + dual mesh)", input, ours.model, ours.timings.totalSeconds);
        print(row);
        std::printf("    sampling %.2f s, mesh building %.2f s, %zu ledger records\n",
                    ours.timings.samplingSeconds, ours.timings.meshSeconds, ours.ledger.size());
        clock.print(ours.timings.totalSeconds);
        std::vector<double> totals{ours.timings.totalSeconds};
        for (int r = 1; r < repeat; ++r) {
            const RemeshResult again = remeshModel(input, params);
            if (computeMeshStatistics(again.model).vertices != row.stats.vertices
                || again.ledger.size() != ours.ledger.size())
                throw std::runtime_error("run " + std::to_string(r + 1)
                                         + " gave another model than the first");
            std::printf("    run %d: %.2f s (sampling %.2f s, mesh building %.2f s)\n", r + 1,
                        again.timings.totalSeconds, again.timings.samplingSeconds,
                        again.timings.meshSeconds);
            totals.push_back(again.timings.totalSeconds);
        }
        printSpread("ours", totals);

        // The same target edge length for CGAL: the one our number of sites stands for.
        double area = 0.0;
        for (const Surface &s : input.surfaces)
            for (const Triangle &t : s.triangles)
                area += 0.5
                        * (s.vertices[t[1]] - s.vertices[t[0]])
                              .cross(s.vertices[t[2]] - s.vertices[t[0]])
                              .norm();
        const double edge = std::sqrt(area / (params.sites * std::sqrt(3.0) / 2.0));
        std::printf("    target edge length %.1f\n", edge);
        for (bool protect : {true, false}) {
            const auto start = std::chrono::steady_clock::now();
            const Model cgal = cgalRemesh(input, edge, protect);
            print(
                measure(protect ? "CGAL isotropic, lines protected" : "CGAL isotropic, lines split",
                        input, cgal, since(start)));
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "stratamesh-bench: remesh: %s\n", e.what());
        return 1;
    }
    return 0;
}

} // namespace stratamesh::bench
