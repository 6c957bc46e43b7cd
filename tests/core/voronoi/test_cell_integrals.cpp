// Per-site integrals of the restricted Voronoi diagram: the cells partition the surfaces and the
// lines exactly, including degenerate site sets (grids, sites equidistant from the surface).
#include "core/voronoi/test_shapes.h"
#include "voronoi/cell_integrals.h"

#include <QtTest>

#include <numeric>

using namespace stratamesh;

Q_DECLARE_METATYPE(std::vector<stratamesh::Vec3>)

namespace {

double sum(const std::vector<double> &v)
{
    return std::accumulate(v.begin(), v.end(), 0.0);
}

CellIntegrals integrate(const RestrictionDomain &d, const std::vector<Vec3> &sites)
{
    const VoronoiNeighbours dt(sites);
    CellIntegralsWorkspace ws;
    return integrateCells(d, dt, {}, ws);
}

// Grid of m×m sites at the centres of the squares of [0,1]², at height z.
std::vector<Vec3> gridSites(int m, double z)
{
    std::vector<Vec3> s;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i)
            s.push_back({(i + 0.5) / m, (j + 0.5) / m, z});
    return s;
}

} // namespace

class TestCellIntegrals : public QObject {
    Q_OBJECT
private slots:
    void sphereAreaIsPartitioned()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        for (unsigned seed : {1u, 2u, 3u}) {
            const auto sites =
                test::randomPointsInBox(200, Vec3(-1.2, -1.2, -1.2), Vec3(1.2, 1.2, 1.2), seed);
            const CellIntegrals ci = integrate(d, sites);
            QVERIFY(std::abs(sum(ci.area) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
            QVERIFY(std::abs(sum(ci.mass) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
            for (double e : ci.energy)
                QVERIFY(e >= 0);
        }
    }

    void gridCellsAreSquares_data()
    {
        QTest::addColumn<double>("z");
        QTest::addColumn<int>("mesh");
        QTest::newRow("coplanar sites, aligned mesh") << 0.0 << 20;
        QTest::newRow("coplanar sites, other mesh") << 0.0 << 13;
        QTest::newRow("sites above the plane") << 0.25 << 20;
    }
    void gridCellsAreSquares()
    {
        QFETCH(double, z);
        QFETCH(int, mesh);
        const int m = 5;
        const RestrictionDomain d = test::squareDomain(mesh);
        const auto sites = gridSites(m, z);
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.area) - 1.0) <= 1e-12);
        for (int i = 0; i < m * m; ++i) {
            QVERIFY2(std::abs(ci.area[i] - 1.0 / (m * m)) <= 1e-12,
                     qPrintable(QString::number(ci.area[i])));
            // Centroid at the site's projection: the moment about the site has no x, y part.
            QVERIFY(std::abs(ci.moment[i].x()) <= 1e-14 && std::abs(ci.moment[i].y()) <= 1e-14);
            QVERIFY(std::abs(ci.moment[i].z() + z * ci.mass[i]) <= 1e-14);
        }
        QVERIFY(std::abs(sum(ci.length) - 4.0) <= 1e-12);
        // Border cells get 1/m of border per side, corner cells twice that.
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const int sides = (i == 0) + (i == m - 1) + (j == 0) + (j == m - 1);
                QVERIFY(std::abs(ci.length[j * m + i] - sides / double(m)) <= 1e-12);
            }
    }

    void plane_equidistant_from_two_layers()
    {
        // Every point of the square is at the same distance from the sites above and below:
        // the symbolic perturbation gives each column to its lower index, with no gap or overlap.
        const int m = 4;
        std::vector<Vec3> sites = gridSites(m, -0.5);
        const auto upper = gridSites(m, 0.5);
        sites.insert(sites.begin(), upper.begin(), upper.end()); // upper layer has lower indices
        const RestrictionDomain d = test::squareDomain(12);
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.area) - 1.0) <= 1e-12);
        for (int i = 0; i < m * m; ++i) {
            QVERIFY(std::abs(ci.area[i] - 1.0 / (m * m)) <= 1e-12);
            QCOMPARE(ci.area[m * m + i], 0.0);
        }
    }

    void fewSitesInLowDimensions_data()
    {
        QTest::addColumn<std::vector<Vec3>>("sites");
        QTest::newRow("one site") << std::vector<Vec3>{{0.3, 0.2, 0.1}};
        QTest::newRow("two sites") << std::vector<Vec3>{{0.3, 0.2, 0.1}, {-0.5, 0.1, 0.0}};
        QTest::newRow("collinear")
            << std::vector<Vec3>{{-0.5, 0, 0}, {0, 0, 0}, {0.5, 0, 0}, {0.9, 0, 0}};
        QTest::newRow("coplanar") << std::vector<Vec3>{
            {-0.5, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, -0.5, 0}, {0.1, 0.1, 0}};
    }
    void fewSitesInLowDimensions()
    {
        QFETCH(std::vector<Vec3>, sites);
        const RestrictionDomain d = test::sphereDomain(2);
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.area) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
        for (double a : ci.area)
            QVERIFY(a > 0);
    }

    void duplicatedSitesKeepTheLowestIndex()
    {
        const RestrictionDomain d = test::sphereDomain(2);
        auto sites = test::randomPointsInBox(40, Vec3(-1, -1, -1), Vec3(1, 1, 1), 9);
        sites[31] = sites[4];
        sites[17] = sites[4];
        sites[2] = sites[39];
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.area) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
        QCOMPARE(ci.area[31], 0.0);
        QCOMPARE(ci.area[17], 0.0);
        QCOMPARE(ci.area[39], 0.0);
        QVERIFY(ci.area[4] > 0 && ci.area[2] > 0);
        const VoronoiNeighbours dt(sites);
        QVERIFY(dt.isHidden(31) && dt.isHidden(17) && dt.isHidden(39) && !dt.isHidden(4)
                && !dt.isHidden(2));
    }

    void lineLengthIsPartitioned()
    {
        const RestrictionDomain d = test::squareDomain(16);
        const auto sites =
            test::randomPointsInBox(60, Vec3(-0.1, -0.1, -0.3), Vec3(1.1, 1.1, 0.3), 7);
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.length) - 4.0) <= 1e-12);
        QVERIFY(std::abs(sum(ci.area) - 1.0) <= 1e-12);
    }

    void densityWeightsMass()
    {
        RestrictionDomain d = test::squareDomain(10, false);
        d.density.resize(d.points.size());
        for (std::size_t i = 0; i < d.points.size(); ++i)
            d.density[i] = 1.0 + d.points[i].x(); // ∫ρ over [0,1]² = 1.5
        finalizeDomain(d);
        const auto sites = test::randomPointsInBox(30, Vec3(0, 0, -0.2), Vec3(1, 1, 0.2), 3);
        const CellIntegrals ci = integrate(d, sites);
        QVERIFY(std::abs(sum(ci.mass) - 1.5) <= 1e-12);
        QVERIFY(std::abs(sum(ci.area) - 1.0) <= 1e-12);
    }
};

QTEST_GUILESS_MAIN(TestCellIntegrals)
#include "test_cell_integrals.moc"
