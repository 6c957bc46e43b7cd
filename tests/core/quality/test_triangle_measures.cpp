// Per-triangle measures, bin membership and worst-first order on models built in code.
#include "common/error.h"
#include "quality/mesh_statistics.h"
#include "quality/triangle_measures.h"
#include "quality/triangle_quality.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

// A floor of an equilateral triangle and a right isoceles one, and a needle on a second surface:
// three distinct qualities, the needle the worst.
Model threeTriangles()
{
    Model m;
    Surface floor;
    floor.name = "floor";
    floor.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2.0, 0),
                      Vec3(0, 1, 0)};
    floor.triangles = {Triangle{0, 1, 2}, Triangle{0, 1, 3}};
    Surface needle;
    needle.name = "needle";
    needle.vertices = {Vec3(0, 0, 1), Vec3(10, 0, 1), Vec3(5, 0.1, 1)};
    needle.triangles = {Triangle{0, 1, 2}};
    m.surfaces = {floor, needle};
    return m;
}

} // namespace

class TestTriangleMeasures : public QObject {
    Q_OBJECT
private slots:
    void oneValuePerTriangleAsTriangleShape()
    {
        const Model m = threeTriangles();
        const auto q = triangleMeasures(m, TriangleMeasure::Quality);
        QCOMPARE(q.size(), std::size_t(2));
        QCOMPARE(q[0].size(), std::size_t(2));
        QCOMPARE(q[1].size(), std::size_t(1));
        QVERIFY(std::abs(q[0][0] - 1.0) < 1e-12);
        const auto &s = m.surfaces[1];
        QCOMPARE(q[1][0], triangleQuality(s.vertices[0], s.vertices[1], s.vertices[2]));
        const auto a = triangleMeasures(m, TriangleMeasure::MinAngle);
        QVERIFY(std::abs(a[0][0] - 60.0) < 1e-9);
        QVERIFY(std::abs(a[0][1] - 45.0) < 1e-9);
    }

    void binMembersAreTheBarsCount()
    {
        const Model m = threeTriangles();
        const Histogram h = qualityHistogram(m);
        for (int bin = 0; bin < int(h.binCount()); ++bin)
            QCOMPARE(trianglesInBin(m, TriangleMeasure::Quality, h, bin).size(),
                     h.counts()[std::size_t(bin)]);
        // Q = 1 falls in the closed last bin, as Histogram::add counts it.
        const auto last = trianglesInBin(m, TriangleMeasure::Quality, h, int(h.binCount()) - 1);
        QCOMPARE(last.size(), std::size_t(1));
        QCOMPARE(last[0].surface, 0);
        QCOMPARE(last[0].triangle, 0);
        QVERIFY(trianglesInBin(m, TriangleMeasure::Quality, h, -1).empty());
        QVERIFY(trianglesInBin(m, TriangleMeasure::Quality, h, 99).empty());
    }

    void worstFirst()
    {
        const Model m = threeTriangles();
        const auto order = trianglesByMeasure(m, TriangleMeasure::Quality);
        QCOMPARE(order.size(), std::size_t(3));
        QCOMPARE(order[0].surface, 1); // the needle
        QVERIFY(order[0].value <= order[1].value && order[1].value <= order[2].value);
        QVERIFY((order[0].centroid - Vec3(5, 0.1 / 3.0, 1)).norm() < 1e-12);
    }

    void binOfMatchesAdd()
    {
        Histogram h({0.0, 1.0, 2.0});
        QCOMPARE(h.binOf(0.0), 0);
        QCOMPARE(h.binOf(1.0), 1);
        QCOMPARE(h.binOf(2.0), 1);
        QCOMPARE(h.binOf(-0.5), -1);
        QCOMPARE(h.binOf(std::nan("")), -1);
        QCOMPARE(h.binOf(2.5), -2);
    }

    void vertexDistancesToAnotherModel()
    {
        const Model m = threeTriangles();
        Model plane;
        Surface s;
        s.name = "plane";
        s.vertices = {Vec3(-100, -100, 0), Vec3(100, -100, 0), Vec3(0, 100, 0)};
        s.triangles = {Triangle{0, 1, 2}};
        plane.surfaces = {s};
        const auto d = vertexDistances(m, plane);
        QCOMPARE(d.size(), std::size_t(2));
        QCOMPARE(d[0].size(), std::size_t(4));
        for (double v : d[0])
            QVERIFY(std::abs(v) < 1e-12);
        for (double v : d[1])
            QVERIFY(std::abs(v - 1.0) < 1e-12);
        QVERIFY_THROWS_EXCEPTION(InputError, vertexDistances(m, Model{}));
    }
};

QTEST_APPLESS_MAIN(TestTriangleMeasures)
#include "test_triangle_measures.moc"
