// Dual faces of the restricted Voronoi diagram (thesis §4.4.1–4.4.2, Algorithm 4.3 step 3) on
// flat squares built in code. Sites at the centres of a square tiling: every interior tiling
// vertex is a Voronoi vertex of four cells, which the symbolic perturbation splits into two RVD
// vertices of three cells, so the dual is each square of four neighbouring sites cut into two
// right triangles, oriented like the input.
#include "remesh/dual_faces.h"

#include "remesh_test_models.h"
#include "voronoi/restricted_voronoi.h"
#include "voronoi/restriction_domain.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <cmath>
#include <map>
#include <set>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

struct Dual {
    CellPoints points;
    std::vector<OutputTriangle> triangles;
    DualFaceCounts counts;
};

Dual dualOf(const Model &model, const std::vector<Vec3> &sites)
{
    const RestrictionDomain domain = makeRestrictionDomain(model);
    const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(domain, sites);
    const CellComponents components = computeCellComponents(domain, rvd);
    SimplificationLedger ledger;
    Dual d;
    d.points = computeCellPoints(model, domain, rvd, components, {}, ledger);
    d.triangles = buildDualFaces(domain, rvd, components, d.points, d.counts);
    return d;
}

} // namespace

class TestDualFaces : public QObject {
    Q_OBJECT

private slots:
    void squareTilingGivesTwoTrianglesPerSquare_data()
    {
        QTest::addColumn<int>("k");
        QTest::addColumn<int>("n");
        QTest::newRow("2 sites a side") << 2 << 5;
        QTest::newRow("4 sites a side") << 4 << 7;
        QTest::newRow("5 sites a side") << 5 << 9;
    }

    void squareTilingGivesTwoTrianglesPerSquare()
    {
        QFETCH(int, k);
        QFETCH(int, n); // input grid, not aligned with the Voronoi edges
        Model m;        // no topology: no line, each cell's point is its centroid (the site)
        m.surfaces = {flatSquare(n, 0.0, "square")};
        const double h = 1.0 / k;
        const std::vector<Vec3> sites = gridSites(k, k, h);
        const Dual d = dualOf(m, sites);
        QCOMPARE(int(d.points.points.size()), k * k);
        QCOMPARE(d.counts.incompleteVertices, 0);
        QCOMPARE(d.counts.arcPolygons, 0);
        QCOMPARE(d.counts.collapsedFaces, 0);
        QCOMPARE(d.counts.vertexTriangles, 2 * (k - 1) * (k - 1));
        QCOMPARE(int(d.triangles.size()), 2 * (k - 1) * (k - 1));

        // Grid index of each output point: that of its site.
        auto cellOf = [&](int p) {
            const int site = d.points.points[std::size_t(p)].site;
            return std::pair<int, int>{site % k, site / k};
        };
        std::map<std::pair<int, int>, int> perSquare; // lower-left cell → triangles in it
        std::map<std::pair<int, int>, int> edgeUse;
        double area = 0.0;
        for (const OutputTriangle &t : d.triangles) {
            QCOMPARE(t.surface, 0);
            const Vec3 &a = d.points.points[std::size_t(t.v[0])].position;
            const Vec3 &b = d.points.points[std::size_t(t.v[1])].position;
            const Vec3 &c = d.points.points[std::size_t(t.v[2])].position;
            // Facing up like the input, about half a square of side h (the points are near,
            // not at, the sites: see test_output_points).
            const double half = (b - a).cross(c - a).z() / 2;
            QVERIFY2(half > 0.5 * h * h / 2 && half < 1.5 * h * h / 2,
                     qPrintable(QString::number(half / (h * h / 2))));
            area += half;
            int minI = k, minJ = k, maxI = -1, maxJ = -1;
            for (int v : t.v) {
                const auto [i, j] = cellOf(v);
                minI = std::min(minI, i);
                minJ = std::min(minJ, j);
                maxI = std::max(maxI, i);
                maxJ = std::max(maxJ, j);
            }
            // Three of the four sites around one tiling vertex.
            QCOMPARE(maxI - minI, 1);
            QCOMPARE(maxJ - minJ, 1);
            ++perSquare[{minI, minJ}];
            for (int e = 0; e < 3; ++e)
                ++edgeUse[std::minmax(t.v[e], t.v[(e + 1) % 3])];
        }
        QCOMPARE(int(perSquare.size()), (k - 1) * (k - 1));
        for (const auto &[square, count] : perSquare)
            QCOMPARE(count, 2);
        // A manifold mesh: each edge in one or two triangles; border edges make the hull.
        int border = 0;
        for (const auto &[edge, use] : edgeUse) {
            QVERIFY(use == 1 || use == 2);
            border += use == 1 ? 1 : 0;
        }
        QCOMPARE(border, 4 * (k - 1));
        // Triangles do not overlap: they tile the hull of the points, about the square of the
        // sites ((k − 1) h)².
        QVERIFY2(std::abs(area - (k - 1) * (k - 1) * h * h) < 0.1 * (k - 1) * (k - 1) * h * h,
                 qPrintable(QString::number(area)));
    }

    // Two squares sharing a line: the dual faces keep each input surface apart (no triangle
    // mixes them) and use the line's points on both sides, so the output is conformal there.
    void facesStayOnTheirSurfaceAndMeetOnTheLine()
    {
        const Model m = twoSquares(7);
        const Dual d = dualOf(m, gridSites(8, 4, 0.25, 0.01));
        QCOMPARE(d.counts.incompleteVertices, 0);
        std::set<int> usedWest, usedEast;
        double area[2] = {0.0, 0.0};
        for (const OutputTriangle &t : d.triangles) {
            QVERIFY(t.surface == 0 || t.surface == 1);
            const Vec3 &a = d.points.points[std::size_t(t.v[0])].position;
            const Vec3 &b = d.points.points[std::size_t(t.v[1])].position;
            const Vec3 &c = d.points.points[std::size_t(t.v[2])].position;
            QVERIFY((b - a).cross(c - a).z() > 0.0); // oriented like the input
            area[t.surface] += (b - a).cross(c - a).z() / 2;
            for (int v : t.v) {
                const double x = d.points.points[std::size_t(v)].position.x();
                QVERIFY2(t.surface == 0 ? x <= 1.0 : x >= 1.0, qPrintable(QString::number(x)));
                (t.surface == 0 ? usedWest : usedEast).insert(v);
            }
        }
        // Points on the shared line (both corners included) are used by both surfaces.
        int shared = 0;
        for (std::size_t p = 0; p < d.points.points.size(); ++p)
            if (d.points.points[p].position.x() == 1.0) {
                QVERIFY(usedWest.count(int(p)) && usedEast.count(int(p)));
                ++shared;
            }
        QVERIFY(shared >= 4); // the two corners and a point per cell along the line between
        // Border points sit on the border: the output covers each square but for rounding of the
        // line points' placement along the line.
        QVERIFY2(std::abs(area[0] - 1.0) < 0.05 && std::abs(area[1] - 1.0) < 0.05,
                 qPrintable(QStringLiteral("%1 %2").arg(area[0]).arg(area[1])));
    }
};

QTEST_APPLESS_MAIN(TestDualFaces)
#include "test_dual_faces.moc"
