// Models built in code with hand-computed statistics.
#include "common/error.h"
#include "quality/mesh_statistics.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

// Unit square z = 0 (two right isoceles triangles) and the square x = 1 standing on its edge;
// they share 2 points, so 6 unique vertices of 8 local ones.
Model foldedSquares()
{
    Model m;
    Surface floor;
    floor.name = "floor";
    floor.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    floor.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
    Surface wall;
    wall.name = "wall";
    wall.vertices = {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1), Vec3(1, 0, 1)};
    wall.triangles = {Triangle{0, 1, 2}, Triangle{0, 2, 3}};
    m.surfaces = {floor, wall};
    return m;
}

void addTopology(Model &m)
{
    m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),
                  Vec3(0, 1, 0), Vec3(1, 1, 1), Vec3(1, 0, 1)};
    m.surfaceVertexToGlobal = {{0, 1, 2, 3}, {1, 2, 4, 5}};
}

const double kRightIsocelesQ = 3.0 / (std::sqrt(6.0) + std::sqrt(3.0));

} // namespace

class TestMeshStatistics : public QObject {
    Q_OBJECT
private slots:
    void perSurfaceWithoutTopology()
    {
        const MeshStatistics s = computeMeshStatistics(foldedSquares());
        QCOMPARE(s.vertices, std::size_t(8));
        QCOMPARE(s.triangles, std::size_t(4));
        QVERIFY(std::abs(s.minAngleDeg - 45.0) < 1e-10);
        QCOMPARE(s.pctTrianglesAngleBelow30, 0.0);
        QVERIFY(std::abs(s.meanQuality - kRightIsocelesQ) < 1e-12);
        QVERIFY(std::abs(s.area - 2.0) < 1e-12);
        QVERIFY(std::abs(s.bboxDiagonal - std::sqrt(3.0)) < 1e-12);
    }

    void mergedVerticesWithTopology()
    {
        Model m = foldedSquares();
        addTopology(m);
        const MeshStatistics s = computeMeshStatistics(m);
        QCOMPARE(s.vertices, std::size_t(6));
        QCOMPARE(s.triangles, std::size_t(4));
        QVERIFY(std::abs(s.area - 2.0) < 1e-12);
    }

    void sharpTrianglesAreCounted()
    {
        // Adds a triangle with legs 2 and 1: angles atan(1/2) = 26.565°, 63.435°, 90°;
        // S = 1, hmax = √5, p = (3 + √5)/2.
        Model m = foldedSquares();
        Surface sharp;
        sharp.name = "sharp";
        sharp.vertices = {Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(0, 1, 5)};
        sharp.triangles = {Triangle{0, 1, 2}};
        m.surfaces.push_back(sharp);
        const MeshStatistics s = computeMeshStatistics(m);
        const double qSharp =
            6.0 / (std::sqrt(3.0) * std::sqrt(5.0) * (3.0 + std::sqrt(5.0)) / 2.0);
        QCOMPARE(s.triangles, std::size_t(5));
        QVERIFY(std::abs(s.minAngleDeg - std::atan(0.5) * 180.0 / M_PI) < 1e-10);
        QVERIFY(std::abs(s.pctTrianglesAngleBelow30 - 20.0) < 1e-12);
        QVERIFY(std::abs(s.meanQuality - (4 * kRightIsocelesQ + qSharp) / 5.0) < 1e-12);
        QVERIFY(std::abs(s.area - 3.0) < 1e-12);
        QVERIFY(std::abs(s.bboxDiagonal - std::sqrt(4.0 + 1.0 + 25.0)) < 1e-12);

        const MeshStatistics one = computeMeshStatistics(m.surfaces[2]);
        QCOMPARE(one.vertices, std::size_t(3));
        QVERIFY(std::abs(one.meanQuality - qSharp) < 1e-12);
        QVERIFY(std::abs(one.bboxDiagonal - std::sqrt(5.0)) < 1e-12);
    }

    void emptyModelIsAllZero()
    {
        const MeshStatistics s = computeMeshStatistics(Model{});
        QCOMPARE(s.vertices, std::size_t(0));
        QCOMPARE(s.triangles, std::size_t(0));
        QCOMPARE(s.minAngleDeg, 0.0);
        QCOMPARE(s.meanQuality, 0.0);
        QCOMPARE(s.bboxDiagonal, 0.0);
    }

    void histogramsUseTheGivenBins()
    {
        const Model m = foldedSquares();
        const Histogram angles = minAngleHistogram(m);
        QCOMPARE(angles.edges(), minAngleBinEdges());
        QCOMPARE(angles.binCount(), std::size_t(12));
        QCOMPARE(angles.total(), std::size_t(4));
        QCOMPARE(angles.counts()[9], std::size_t(4)); // 45° in [45, 50)
        const Histogram q = qualityHistogram(m);
        QCOMPARE(q.binCount(), std::size_t(20));
        QCOMPARE(q.counts()[14], std::size_t(4)); // 0.717 in [0.70, 0.75)

        const Histogram coarse = qualityHistogram(m, {0.0, 0.5, 1.0});
        QCOMPARE(coarse.counts(), (std::vector<std::size_t>{0, 4}));
    }

    void badIndexThrows()
    {
        Model m = foldedSquares();
        m.surfaces[1].triangles.push_back(Triangle{0, 1, 4});
        QVERIFY_THROWS_EXCEPTION(InputError, computeMeshStatistics(m));
        QVERIFY_THROWS_EXCEPTION(InputError, qualityHistogram(m));
    }
};

QTEST_GUILESS_MAIN(TestMeshStatistics)
#include "test_mesh_statistics.moc"
