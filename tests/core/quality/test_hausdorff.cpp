// Hausdorff distance (thesis Table 4.2) on shapes whose distance is known exactly, and the
// comparison rows built on it (input vs output, run vs run).
#include "model/topology.h"
#include "quality/hausdorff.h"
#include "quality/model_comparison.h"

#include "common/error.h"

#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

// Axis-aligned rectangle [x0, x1] × [y0, y1] at height z, two triangles.
Surface rectangle(double x0, double x1, double y0, double y1, double z)
{
    Surface s;
    s.name = "rect";
    s.vertices = {Vec3(x0, y0, z), Vec3(x1, y0, z), Vec3(x1, y1, z), Vec3(x0, y1, z)};
    s.triangles = {{0, 1, 2}, {0, 2, 3}};
    return s;
}

Model modelOf(std::vector<Surface> surfaces)
{
    Model m;
    m.name = "m";
    m.surfaces = std::move(surfaces);
    return m;
}

} // namespace

class TestHausdorff : public QObject {
    Q_OBJECT
private slots:
    void parallelSquares()
    {
        const Model a = modelOf({rectangle(0, 1, 0, 1, 0)});
        const Model b = modelOf({rectangle(0, 1, 0, 1, 0.25)});
        const HausdorffResult r = hausdorffDistance(a, b, HausdorffParams{2000});
        QVERIFY(std::abs(r.aToB - 0.25) < 1e-12);
        QVERIFY(std::abs(r.bToA - 0.25) < 1e-12);
        QVERIFY(std::abs(r.meanAToB - 0.25) < 1e-12);
        QVERIFY(std::abs(r.bboxDiagonal - std::sqrt(2.0)) < 1e-12);
        QVERIFY(std::abs(r.symmetricPctBbox - 25.0 / std::sqrt(2.0)) < 1e-9);
        QCOMPARE(r.vertexDistanceBToA.size(), std::size_t(1));
        for (double d : r.vertexDistanceBToA[0])
            QVERIFY(std::abs(d - 0.25) < 1e-12);
    }

    void asymmetricCover()
    {
        // B covers the left half of A: every point of B is on A, A's right edge is 0.5 from B.
        const Model a = modelOf({rectangle(0, 1, 0, 1, 0)});
        const Model b = modelOf({rectangle(0, 0.5, 0, 1, 0)});
        const HausdorffResult r = hausdorffDistance(a, b, HausdorffParams{5000});
        QVERIFY(std::abs(r.aToB - 0.5) < 1e-12);
        QVERIFY(r.bToA < 1e-12);
        QVERIFY(std::abs(r.symmetric - 0.5) < 1e-12);
        QVERIFY(r.meanAToB > 0.1 && r.meanAToB < 0.15); // ≈ 1/8 for uniform samples
    }

    void distanceToTriangleInterior()
    {
        // A point above the middle of a big triangle is closer to its interior than to any vertex:
        // the distance must be exact, not a sample-to-sample distance.
        const Model a = modelOf({rectangle(-10, 10, -10, 10, 0)});
        const std::vector<double> d = distancesToModel(a, {Vec3(0.3, -0.7, 2.0), Vec3(12, 0, 0)});
        QVERIFY(std::abs(d[0] - 2.0) < 1e-12);
        QVERIFY(std::abs(d[1] - 2.0) < 1e-12);
    }

    void comparisonRows()
    {
        // A square of two triangles against the same square split into four (a finer "output").
        const Model a = recoverTopology(modelOf({rectangle(0, 2, 0, 2, 0)}));
        Surface fine;
        fine.name = "rect";
        fine.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0),
                         Vec3(1, 1, 0.1)};
        fine.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
        const Model b = recoverTopology(modelOf({fine}));
        const ModelComparison c = compareModels(a, b, HausdorffParams{4000});
        QCOMPARE(c.input.mesh.triangles, std::size_t(2));
        QCOMPARE(c.output.mesh.triangles, std::size_t(4));
        QCOMPARE(c.output.mesh.vertices, std::size_t(5));
        QCOMPARE(c.input.counts.surfaces, 1);
        QVERIFY(std::abs(c.hausdorff.symmetric - 0.1) < 1e-12); // the raised centre
        QVERIFY(std::abs(c.output.hausdorffPctBbox - 10.0 / std::sqrt(8.0)) < 1e-9);
        QVERIFY(c.input.hausdorffPctBbox < 0.0);
        QCOMPARE(c.inputQuality.total(), std::size_t(2));
        QCOMPARE(c.outputQuality.total(), std::size_t(4));
        QCOMPARE(c.inputMinAngle.edges(), c.outputMinAngle.edges());
        const std::string table = formatTable42({c.input, c.output});
        QCOMPARE(std::count(table.begin(), table.end(), '\n'), 4L); // header, rule, two rows
        QVERIFY(table.find("| Input |") != std::string::npos);

        // A distance measured before (a saved run's report) is used as given, not sampled again.
        HausdorffResult saved = c.hausdorff;
        saved.symmetricPctBbox = 1.25;
        const ModelComparison restored = compareModels(a, b, saved);
        QCOMPARE(restored.output.hausdorffPctBbox, 1.25);
        QCOMPARE(restored.output.mesh.triangles, std::size_t(4));
        QCOMPARE(restored.outputQuality.total(), std::size_t(4));

        // Two runs of the same input side by side: each column is a run, with its own distance
        // to the input; nothing of the input is left in the table.
        const Model same = recoverTopology(modelOf({rectangle(0, 2, 0, 2, 0)}));
        const ModelComparison flat = compareModels(a, same, HausdorffParams{4000});
        const ModelComparison runs = compareRuns(restored, flat);
        QCOMPARE(runs.input.mesh.triangles, std::size_t(4));
        QCOMPARE(runs.input.hausdorffPctBbox, 1.25);
        QCOMPARE(runs.output.mesh.triangles, std::size_t(2));
        QVERIFY(runs.output.hausdorffPctBbox >= 0.0 && runs.output.hausdorffPctBbox < 1e-9);
        QCOMPARE(runs.inputQuality.total(), std::size_t(4));
        QCOMPARE(runs.outputQuality.total(), std::size_t(2));
        QCOMPARE(runs.inputMinAngle.total(), std::size_t(4));
        QCOMPARE(runs.hausdorff.symmetricPctBbox, flat.hausdorff.symmetricPctBbox);
        // Runs of different inputs do not go side by side.
        const ModelComparison other = compareModels(b, a, HausdorffParams{400});
        QVERIFY_THROWS_EXCEPTION(InputError, compareRuns(c, other));
    }

    void emptyModelRefused()
    {
        const Model a = modelOf({rectangle(0, 1, 0, 1, 0)});
        QVERIFY_THROWS_EXCEPTION(InputError, hausdorffDistance(a, Model{}));
    }
};

QTEST_GUILESS_MAIN(TestHausdorff)
#include "test_hausdorff.moc"
