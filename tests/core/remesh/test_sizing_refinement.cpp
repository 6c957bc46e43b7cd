// Splitting a model finer than its sizing field (sizing_refinement.h), on a faulted box built in
// code: the geometry, the entities and their incidences must not change, every split edge must
// be shared by all the surfaces and lines that held it, and the edges must end up no longer than
// the size at their finer end where refinement was asked.
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"
#include "remesh/sizing_refinement.h"
#include "remesh/topology_refinement.h"

#include <QtTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <utility>

using namespace stratamesh;

namespace {

Model faultedBox(double faultThrow)
{
    LayeredBoxParams bp;
    bp.size = Vec3(1000, 600, 400);
    bp.horizons = 1;
    bp.fault = true;
    bp.faultThrow = faultThrow;
    bp.edgeLength = 80;
    return recoverTopology(layeredBox(bp));
}

FeatureSizingParams sizing(double edge)
{
    FeatureSizingParams p;
    p.edgeLength = edge;
    p.lfsFactor = 1.0;
    p.minEdgeLength = edge / 64.0;
    return p;
}

double surfaceArea(const Surface &s)
{
    double a = 0.0;
    for (const Triangle &t : s.triangles)
        a += 0.5
             * (s.vertices[t[1]] - s.vertices[t[0]])
                   .cross(s.vertices[t[2]] - s.vertices[t[0]])
                   .norm();
    return a;
}

// Global edges of one surface.
std::set<std::pair<int, int>> surfaceEdges(const Model &m, int s)
{
    std::set<std::pair<int, int>> out;
    for (const Triangle &t : m.surfaces[s].triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = m.surfaceVertexToGlobal[s][t[k]];
            const int b = m.surfaceVertexToGlobal[s][t[(k + 1) % 3]];
            out.emplace(std::min(a, b), std::max(a, b));
        }
    return out;
}

} // namespace

class TestSizingRefinement : public QObject {
    Q_OBJECT
private slots:
    void splitsKeepGeometryAndTopology()
    {
        const Model m = faultedBox(15);
        const SizedModel r = refineToSize(m, sizing(200), {}, 0.0, 8);
        QCOMPARE(r.firstAdded, static_cast<int>(m.vertices.size()));
        QVERIFY2(r.model.vertices.size() > m.vertices.size() + 100,
                 qPrintable(QString::number(r.model.vertices.size())));
        QCOMPARE(r.parents.size(), r.model.vertices.size() - m.vertices.size());
        QCOMPARE(r.size.size(), r.model.vertices.size());
        // Same entities, same corners, same line ends; areas to rounding.
        QCOMPARE(r.model.surfaces.size(), m.surfaces.size());
        QCOMPARE(r.model.lines.size(), m.lines.size());
        QCOMPARE(r.model.corners.size(), m.corners.size());
        for (std::size_t c = 0; c < m.corners.size(); ++c)
            QCOMPARE(r.model.corners[c].vertex, m.corners[c].vertex);
        for (std::size_t s = 0; s < m.surfaces.size(); ++s) {
            const double before = surfaceArea(m.surfaces[s]);
            QVERIFY(std::abs(surfaceArea(r.model.surfaces[s]) - before) <= 1e-9 * before);
        }
        // Each line runs along edges of every surface it bounds: the splits were conformal.
        for (std::size_t l = 0; l < m.lines.size(); ++l) {
            const Line &line = r.model.lines[l];
            QCOMPARE(line.vertices.front(), m.lines[l].vertices.front());
            QCOMPARE(line.vertices.back(), m.lines[l].vertices.back());
            for (int s : line.surfaces) {
                const std::set<std::pair<int, int>> edges = surfaceEdges(r.model, s);
                for (std::size_t i = 0; i + 1 < line.vertices.size(); ++i) {
                    const int a = line.vertices[i], b = line.vertices[i + 1];
                    QVERIFY2(edges.count({std::min(a, b), std::max(a, b)}) == 1,
                             qPrintable(QString("line %1 segment %2").arg(l).arg(i)));
                }
            }
        }
        // An added vertex is the midpoint of its parents: a linear field extends exactly.
        std::vector<double> x;
        for (int v = 0; v < r.firstAdded; ++v)
            x.push_back(r.model.vertices[v].x());
        const std::vector<double> extended = extendToAdded(r, x);
        for (std::size_t v = 0; v < r.model.vertices.size(); ++v)
            QVERIFY(std::abs(extended[v] - r.model.vertices[v].x()) < 1e-9);
        // The split model is as valid as the input (conformal, no intersection).
        QVERIFY(checkValidity(m).valid);
        const ValidityReport report = checkValidity(r.model);
        QVERIFY2(report.valid, report.problems.empty() ? "" : report.problems[0].message.c_str());
    }

    void edgesEndNoLongerThanTheSizeWhereAsked()
    {
        const Model m = faultedBox(15);
        // Around the vertex of finest size (on the cut-off lines of the 15 m throw).
        const std::vector<double> size = refineToSize(m, sizing(200), {}, 0.0, 0).size;
        const auto finest = std::min_element(size.begin(), size.end()) - size.begin();
        QVERIFY(size[finest] < 20.0);
        const Vec3 target = m.vertices[finest];
        const double radius = 150.0;
        const SizedModel r = refineToSize(m, sizing(200), {target}, radius, 10);
        int longNear = 0, addedFar = 0;
        for (std::size_t s = 0; s < r.model.surfaces.size(); ++s)
            for (const auto &[a, b] : surfaceEdges(r.model, static_cast<int>(s))) {
                const Vec3 &pa = r.model.vertices[a], &pb = r.model.vertices[b];
                if ((0.5 * (pa + pb) - target).norm() <= radius
                    && (pa - pb).norm() > std::min(r.size[a], r.size[b]) * (1 + 1e-9))
                    ++longNear;
            }
        for (std::size_t v = r.firstAdded; v < r.model.vertices.size(); ++v)
            addedFar += (r.model.vertices[v] - target).norm() > radius + 80.0;
        QCOMPARE(longNear, 0);
        QCOMPARE(addedFar, 0); // only edges with their midpoint near the target are split
        QVERIFY(r.model.vertices.size() > m.vertices.size());
    }

    // Pinned sites (topology_refinement.h): one on every corner near a target, and one every
    // size of length along the lines, none where the size is the coarse one.
    void featureSitesSitOnCornersAndAlongLines()
    {
        const Model m = faultedBox(15);
        const double h = 50.0;
        const std::vector<double> size(m.vertices.size(), h);
        const std::vector<Vec3> everywhere{Vec3(500, 300, 200)};
        const std::vector<Vec3> sites = featureSitesNearTargets(m, size, everywhere, 1e9, 100.0);
        auto count = [&](const Vec3 &p) {
            return std::count_if(sites.begin(), sites.end(),
                                 [&](const Vec3 &s) { return (s - p).norm() < 1e-9; });
        };
        for (const Corner &c : m.corners)
            QCOMPARE(count(m.vertices[c.vertex]), 1);
        double length = 0.0;
        int ends = 0;
        for (const Line &l : m.lines) {
            for (std::size_t i = 0; i + 1 < l.vertices.size(); ++i)
                length += (m.vertices[l.vertices[i + 1]] - m.vertices[l.vertices[i]]).norm();
            ends += l.closed ? 0 : 1;
        }
        const int alongLines = static_cast<int>(sites.size() - m.corners.size());
        // Each open line gets floor(length / h) sites, less the one that would fall on its end.
        QVERIFY2(
            std::abs(alongLines - (length / h - ends)) <= ends,
            qPrintable(
                QString("%1 sites along %2 m of %3 lines").arg(alongLines).arg(length).arg(ends)));
        // Where the size is the coarse one, only the corners are pinned.
        const std::vector<Vec3> coarse = featureSitesNearTargets(
            m, std::vector<double>(m.vertices.size(), 100.0), everywhere, 1e9, 100.0);
        QCOMPARE(coarse.size(), m.corners.size());
    }
};

QTEST_APPLESS_MAIN(TestSizingRefinement)
#include "test_sizing_refinement.moc"
