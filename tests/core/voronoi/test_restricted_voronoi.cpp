// The symbolic restricted Voronoi diagram: exact partition, consistent symbols across cells,
// connected components on surfaces and lines (thesis Fig 1.8, 4.3, 4.4), corners.
#include "core/voronoi/test_shapes.h"
#include "quality/restricted_delaunay_quality.h"
#include "voronoi/restricted_voronoi.h"

#include <QtTest>

#include <tbb/global_control.h>

#include <Eigen/Geometry>

#include <map>
#include <set>

using namespace stratamesh;

namespace {

// Points spread evenly on a sphere (Fibonacci spiral).
std::vector<Vec3> fibonacciSphere(int n, double radius)
{
    std::vector<Vec3> p;
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
        p.push_back(radius * Vec3(r * std::cos(golden * i), r * std::sin(golden * i), z));
    }
    return p;
}

// Every symbol is shared exactly as its kind says, and every bisector edge of a polygon is the
// reversed edge of the neighbour's polygon in the same triangle.
void verifyConsistentSymbols(const RestrictionDomain &d, const RestrictedVoronoiDiagram &rvd)
{
    for (std::size_t v = 0; v < rvd.vertices.size(); ++v) {
        const RvdVertex &vx = rvd.vertices[v];
        std::set<int> sites, triangles;
        for (int p : rvd.polygonsOfVertex(static_cast<int>(v))) {
            sites.insert(rvd.polygons[p].site);
            triangles.insert(rvd.polygons[p].triangle);
        }
        switch (vx.symbol.kind) {
        case RvdVertexKind::FaceVoronoiEdge:
            QCOMPARE(sites, std::set<int>(vx.symbol.sites.begin(), vx.symbol.sites.end()));
            QCOMPARE(rvd.polygonsOfVertex(static_cast<int>(v)).size(), std::size_t(3));
            QCOMPARE(*triangles.begin(), vx.symbol.a);
            break;
        case RvdVertexKind::EdgeBisector:
            if (vx.triangle >= 0) // on surfaces: both cells, in every triangle of the edge
                QCOMPARE(sites, std::set<int>({vx.symbol.sites[0], vx.symbol.sites[1]}));
            QVERIFY(rvd.polygonsOfVertex(static_cast<int>(v)).size() == 2 * triangles.size());
            break;
        case RvdVertexKind::InputVertex:
            QVERIFY(sites.size() <= 1);
            break;
        }
    }
    // Shared bisector edges.
    std::map<std::tuple<int, int, int>, int> edges; // (triangle, from, to) → polygon
    for (std::size_t p = 0; p < rvd.polygons.size(); ++p) {
        const RvdPolygon &poly = rvd.polygons[p];
        for (int k = 0; k < poly.count; ++k)
            edges[{poly.triangle, rvd.polygonVerticesBegin(int(p))[k],
                   rvd.polygonVerticesBegin(int(p))[(k + 1) % poly.count]}] = int(p);
    }
    for (std::size_t p = 0; p < rvd.polygons.size(); ++p) {
        const RvdPolygon &poly = rvd.polygons[p];
        for (int k = 0; k < poly.count; ++k) {
            const int j = rvd.polygonSupportsBegin(int(p))[k];
            if (j < 0)
                continue;
            const auto it =
                edges.find({poly.triangle, rvd.polygonVerticesBegin(int(p))[(k + 1) % poly.count],
                            rvd.polygonVerticesBegin(int(p))[k]});
            QVERIFY(it != edges.end());
            QCOMPARE(rvd.polygons[it->second].site, j);
        }
    }
    Q_UNUSED(d);
}

double polygonArea(const RestrictedVoronoiDiagram &rvd)
{
    double a = 0;
    for (const RvdPolygon &p : rvd.polygons)
        a += p.area;
    return a;
}

} // namespace

class TestRestrictedVoronoi : public QObject {
    Q_OBJECT
private slots:
    void partitionAndSymbols()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        const auto sites =
            test::randomPointsInBox(150, Vec3(-1.1, -1.1, -1.1), Vec3(1.1, 1.1, 1.1), 4);
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, sites);
        QVERIFY(std::abs(polygonArea(rvd) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
        verifyConsistentSymbols(d, rvd);
        double cells = 0;
        for (const RestrictedCell &c : rvd.cells)
            cells += c.area;
        QVERIFY(std::abs(cells - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
        for (const RvdVertex &v : rvd.vertices)
            QVERIFY(std::abs(v.position.norm() - 1.0) < 0.02); // on the (polyhedral) sphere
    }

    void gridCellsAreExpectedSquares()
    {
        const int m = 4, mesh = 16;
        const RestrictionDomain d = test::squareDomain(mesh);
        std::vector<Vec3> sites;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i)
                sites.push_back({(i + 0.5) / m, (j + 0.5) / m, 0.0});
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, sites);
        verifyConsistentSymbols(d, rvd);
        for (int s = 0; s < m * m; ++s) {
            const RestrictedCell &cell = rvd.cells[s];
            QCOMPARE(cell.surfaceComponents.size(), std::size_t(1));
            QVERIFY(std::abs(cell.area - 1.0 / (m * m)) <= 1e-12);
            QVERIFY((cell.centroid - sites[s]).norm() <= 1e-12);
            // The cell's vertices span exactly the square around its site.
            Vec3 lo = Vec3::Constant(1e9), hi = -lo;
            for (int p : rvd.surfaceComponents[cell.surfaceComponents[0]].polygons)
                for (int k = 0; k < rvd.polygons[p].count; ++k) {
                    const Vec3 &x = rvd.vertices[rvd.polygonVerticesBegin(p)[k]].position;
                    lo = lo.cwiseMin(x);
                    hi = hi.cwiseMax(x);
                }
            QVERIFY((lo - (sites[s] - Vec3(0.5 / m, 0.5 / m, 0))).norm() <= 1e-12);
            QVERIFY((hi - (sites[s] + Vec3(0.5 / m, 0.5 / m, 0))).norm() <= 1e-12);
            // Border line: one component for border cells (corners join two sides), none inside.
            const int i = s % m, j = s / m;
            const bool border = i == 0 || j == 0 || i == m - 1 || j == m - 1;
            QCOMPARE(cell.lineComponents.size(), std::size_t(border ? 1 : 0));
        }
        double length = 0;
        for (const RvdLinePiece &p : rvd.linePieces)
            length += p.length;
        QVERIFY(std::abs(length - 4.0) <= 1e-12);
    }

    void sandwichedSitesHaveTwoComponents()
    {
        // Thesis Fig 4.3: sites between two close parallel surfaces.
        const double gap = 0.05;
        const RestrictionDomain d = test::parallelPlanesDomain(20, gap);
        auto sites = test::randomPointsInBox(40, Vec3(0.05, 0.05, 0.4 * gap),
                                             Vec3(0.95, 0.95, 0.6 * gap), 8);
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, sites);
        verifyConsistentSymbols(d, rvd);
        for (const RestrictedCell &cell : rvd.cells) {
            QCOMPARE(cell.surfaceComponents.size(), std::size_t(2));
            QVERIFY(rvd.surfaceComponents[cell.surfaceComponents[0]].surface
                    != rvd.surfaceComponents[cell.surfaceComponents[1]].surface);
        }
        QVERIFY(std::abs(polygonArea(rvd) - 2.0) <= 1e-12);
    }

    void sitesBetweenNestedSpheresHaveTwoComponents()
    {
        // Thesis Fig 4.4: sites between two nested spheres.
        const RestrictionDomain d = test::nestedSpheresDomain(3, 0.95, 1.0);
        const RestrictedVoronoiDiagram rvd =
            computeRestrictedVoronoi(d, fibonacciSphere(80, 0.975));
        verifyConsistentSymbols(d, rvd);
        for (const RestrictedCell &cell : rvd.cells)
            QCOMPARE(cell.surfaceComponents.size(), std::size_t(2));
        // Two far sites split both spheres into caps: still one component per sphere and cell.
        const RestrictedVoronoiDiagram far =
            computeRestrictedVoronoi(d, {Vec3(0, 0, 3), Vec3(0, 0, -3)});
        QCOMPARE(far.cells[0].surfaceComponents.size(), std::size_t(2));
        QCOMPARE(far.cells[1].surfaceComponents.size(), std::size_t(2));
    }

    void linesPiecesAndCorners()
    {
        RestrictionDomain d = test::squareDomain(10);
        d.corners = {0, 10, 120, 110}; // the square's corners (grid 11×11 points)
        finalizeDomain(d);
        const auto sites = test::randomPointsInBox(25, Vec3(0, 0, -0.2), Vec3(1, 1, 0.2), 12);
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, sites);
        double length = 0;
        for (const RvdLineComponent &c : rvd.lineComponents)
            length += c.length;
        QVERIFY(std::abs(length - 4.0) <= 1e-12);
        // Pieces of a component chain: each ends where the next starts.
        for (const RvdLineComponent &c : rvd.lineComponents)
            for (std::size_t k = 1; k < c.pieces.size(); ++k)
                QCOMPARE(rvd.linePieces[c.pieces[k]].vertices[0],
                         rvd.linePieces[c.pieces[k - 1]].vertices[1]);
        // Corners belong to the cell of their nearest site.
        for (std::size_t c = 0; c < d.corners.size(); ++c) {
            const Vec3 &x = d.points[d.corners[c]];
            int best = 0;
            for (std::size_t s = 1; s < sites.size(); ++s)
                if ((sites[s] - x).norm() < (sites[best] - x).norm())
                    best = int(s);
            QCOMPARE(rvd.cornerSites[c], best);
            const auto &corners = rvd.cells[best].corners;
            QVERIFY(std::find(corners.begin(), corners.end(), int(c)) != corners.end());
        }
        // Line vertices on the border are the surface's edge vertices (shared symbols).
        for (const RvdLinePiece &p : rvd.linePieces)
            for (int v : p.vertices)
                QVERIFY(rvd.vertexPolygonOffsets[v + 1] > rvd.vertexPolygonOffsets[v]);
    }

    void identicalWhateverTheThreadCount()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        const auto sites = test::randomPointsInBox(300, Vec3(-1, -1, -1), Vec3(1, 1, 1), 21);
        RestrictedVoronoiDiagram one, two;
        {
            tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
            one = computeRestrictedVoronoi(d, sites);
        }
        {
            tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
            two = computeRestrictedVoronoi(d, sites);
        }
        QCOMPARE(one.vertices.size(), two.vertices.size());
        for (std::size_t v = 0; v < one.vertices.size(); ++v) {
            QVERIFY(one.vertices[v].symbol == two.vertices[v].symbol);
            QVERIFY(one.vertices[v].position == two.vertices[v].position);
        }
        QVERIFY(one.polygonVertices == two.polygonVertices);
    }

    void nearestNeighboursGiveTheSameDiagram_data()
    {
        QTest::addColumn<int>("shape");
        QTest::newRow("random sites around a sphere") << 0;
        QTest::newRow("grid of coplanar sites") << 1;
        QTest::newRow("dense cluster in a corner") << 2;
        QTest::newRow("sandwiched sites") << 3;
    }
    void nearestNeighboursGiveTheSameDiagram()
    {
        // Both neighbour searches must give the same exact diagram: same symbols, same polygons.
        QFETCH(int, shape);
        RestrictionDomain d;
        std::vector<Vec3> sites;
        if (shape == 0) {
            d = test::sphereDomain(3);
            sites = test::randomPointsInBox(200, Vec3(-1.2, -1.2, -1.2), Vec3(1.2, 1.2, 1.2), 31);
        } else if (shape == 1) {
            d = test::squareDomain(16);
            for (int j = 0; j < 6; ++j)
                for (int i = 0; i < 6; ++i)
                    sites.push_back({(i + 0.5) / 6, (j + 0.5) / 6, 0.0});
        } else if (shape == 2) {
            // Cells far larger than the 24 nearest sites reach: the lists must be completed.
            d = test::squareDomain(12);
            sites = test::randomPointsInBox(300, Vec3(0, 0, -0.02), Vec3(0.08, 0.08, 0.02), 32);
            sites.push_back({0.9, 0.9, 0.5});
        } else {
            d = test::parallelPlanesDomain(12, 0.05);
            sites = test::randomPointsInBox(80, Vec3(0, 0, 0.02), Vec3(1, 1, 0.03), 33);
        }
        const RestrictedVoronoiDiagram a =
            computeRestrictedVoronoi(d, sites, Progress::none(), NeighbourSearch::Delaunay);
        const RestrictedVoronoiDiagram b = computeRestrictedVoronoi(
            d, sites, Progress::none(), NeighbourSearch::NearestNeighbours);
        QCOMPARE(a.vertices.size(), b.vertices.size());
        for (std::size_t v = 0; v < a.vertices.size(); ++v) {
            QVERIFY(a.vertices[v].symbol == b.vertices[v].symbol);
            QVERIFY(a.vertices[v].position == b.vertices[v].position); // canonical from the symbol
        }
        QVERIFY(a.polygonVertices == b.polygonVertices);
        QVERIFY(a.polygonSupports == b.polygonSupports);
        QCOMPARE(a.linePieces.size(), b.linePieces.size());
        QCOMPARE(a.surfaceComponents.size(), b.surfaceComponents.size());
        for (std::size_t p = 0; p < a.polygons.size(); ++p)
            QVERIFY(std::abs(a.polygons[p].area - b.polygons[p].area)
                    <= 1e-12 * (1 + a.polygons[p].area));
        QVERIFY(std::abs(polygonArea(b) - d.surfaceArea()) <= 1e-9 * d.surfaceArea());
        verifyConsistentSymbols(d, b);
    }

    void neighbourHintsGiveTheSameLists()
    {
        // Hints only start the k-nearest searches: whatever they hold (the lists of moved sites,
        // repeated, out of range or wrong entries), the lists, distances and complete radii
        // are those found without them.
        std::vector<Vec3> sites = test::randomPointsInBox(400, Vec3(0, 0, 0), Vec3(1, 1, 0.1), 41);
        const VoronoiNeighbours before(sites, NeighbourSearch::NearestNeighbours);
        NeighbourHints hints;
        before.exportHints(hints);
        QCOMPARE(static_cast<int>(hints.offsets.size()), 401);
        for (std::size_t i = 0; i < sites.size(); ++i)
            sites[i] += 0.02 * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), 0.1 * std::sin(7.0 * i));
        NeighbourHints bad = hints;
        for (std::size_t h = 0; h < bad.neighbours.size(); h += 3)
            bad.neighbours[h] = h % 2 ? -5 : static_cast<int>((h * 7919) % 400);
        if (!bad.neighbours.empty())
            bad.neighbours[0] = 100000;
        const VoronoiNeighbours plain(sites, NeighbourSearch::NearestNeighbours);
        for (const NeighbourHints *h : {&hints, &bad}) {
            const VoronoiNeighbours hinted(sites, NeighbourSearch::NearestNeighbours, h);
            for (int i = 0; i < plain.siteCount(); ++i) {
                QCOMPARE(hinted.neighbourCount(i), plain.neighbourCount(i));
                QCOMPARE(hinted.completeRadius(i), plain.completeRadius(i));
                for (int k = 0; k < plain.neighbourCount(i); ++k) {
                    QCOMPARE(hinted.neighboursBegin(i)[k], plain.neighboursBegin(i)[k]);
                    QCOMPARE(hinted.neighbourDistances(i)[k], plain.neighbourDistances(i)[k]);
                }
            }
        }
        // The lists really are the nearest: none closer than the complete radius is missing.
        for (int i = 0; i < plain.siteCount(); ++i) {
            int closer = 0;
            for (int j = 0; j < plain.siteCount(); ++j)
                closer += j != i && (sites[j] - sites[i]).norm() < plain.completeRadius(i);
            QVERIFY(closer <= plain.neighbourCount(i));
            for (int k = 0; k < plain.neighbourCount(i); ++k)
                QVERIFY(plain.neighbourDistances(i)[k] <= plain.completeRadius(i));
        }
    }

    void reusedListsHoldEverySiteWithinTheirRadius()
    {
        // Lists reused for moved sites: each is the fresh list cut at its (smaller) complete
        // radius, sorted by the current distances, and no site closer than that radius is missing.
        std::vector<Vec3> sites = test::randomPointsInBox(400, Vec3(0, 0, 0), Vec3(1, 1, 0.1), 42);
        NeighbourReuse reuse;
        const VoronoiNeighbours first(sites, reuse);
        QCOMPARE(reuse.searches, 1);
        QVERIFY(reuse.maxDrift > 0);
        for (std::size_t i = 0; i < sites.size(); ++i)
            sites[i] +=
                0.5 * reuse.maxDrift
                * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), 0.3 * std::sin(7.0 * i)).normalized();
        const VoronoiNeighbours reused(sites, reuse);
        QCOMPARE(reuse.reuses, 1);
        const VoronoiNeighbours fresh(sites, NeighbourSearch::NearestNeighbours);
        int shorter = 0;
        for (int i = 0; i < reused.siteCount(); ++i) {
            const double radius = reused.completeRadius(i);
            QVERIFY(radius <= fresh.completeRadius(i));
            int prefix = 0;
            while (prefix < fresh.neighbourCount(i) && fresh.neighbourDistances(i)[prefix] < radius)
                ++prefix;
            QCOMPARE(reused.neighbourCount(i), prefix);
            shorter += prefix < fresh.neighbourCount(i);
            for (int k = 0; k < prefix; ++k) {
                QCOMPARE(reused.neighboursBegin(i)[k], fresh.neighboursBegin(i)[k]);
                QCOMPARE(reused.neighbourDistances(i)[k], fresh.neighbourDistances(i)[k]);
            }
            int closer = 0;
            for (int j = 0; j < reused.siteCount(); ++j)
                closer += j != i && (sites[j] - sites[i]).norm() < radius;
            QCOMPARE(closer, reused.neighbourCount(i));
            // What the lists lack, the kd-tree gives: the same sites as the fresh list's tail.
            std::vector<std::pair<double, int>> beyond;
            reused.sitesBeyondList(i, fresh.completeRadius(i), beyond);
            for (int k = prefix; k < fresh.neighbourCount(i); ++k)
                QVERIFY(std::find(beyond.begin(), beyond.end(),
                                  std::make_pair(fresh.neighbourDistances(i)[k],
                                                 fresh.neighboursBegin(i)[k]))
                        != beyond.end());
        }
        QVERIFY(shorter > 0); // the cut happened somewhere
        // A site moving farther than the drift allowed: searched again.
        sites[7] += Vec3(2 * reuse.maxDrift, 0, 0);
        const VoronoiNeighbours again(sites, reuse);
        QCOMPARE(reuse.searches, 2);
        QCOMPARE(reuse.reuses, 1);
    }

    void everyTriangleIsTiled()
    {
        // Each triangle's polygons add up to its area, also where dozens of small cells crowd a
        // large triangle and where cuts graze bisectors (positions recomputed from symbols).
        RestrictionDomain d = test::squareDomain(6);
        auto sites = test::randomPointsInBox(400, Vec3(0, 0, -0.01), Vec3(0.1, 0.1, 0.01), 41);
        for (int k = 0; k < 20; ++k) // sites on the diagonal of triangle 0, equidistant pairs
            sites.push_back({0.01 * k, 0.01 * k + 1e-12 * k, 0.0});
        sites.push_back({0.9, 0.9, 0.5});
        finalizeDomain(d);
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, sites);
        std::vector<double> tiled(d.triangles.size(), 0.0);
        for (const RvdPolygon &p : rvd.polygons)
            tiled[p.triangle] += p.area;
        for (std::size_t t = 0; t < d.triangles.size(); ++t) {
            const Triangle &tri = d.triangles[t];
            const double area = 0.5
                                * (d.points[tri[1]] - d.points[tri[0]])
                                      .cross(d.points[tri[2]] - d.points[tri[0]])
                                      .norm();
            QVERIFY2(std::abs(tiled[t] - area) <= 1e-12 * area,
                     qPrintable(QString("triangle %1").arg(t)));
        }
        verifyConsistentSymbols(d, rvd);
    }

    void restrictedDelaunayOfSphere()
    {
        const RestrictionDomain d = test::sphereDomain(4);
        const auto sites = fibonacciSphere(60, 1.0);
        const RestrictedDelaunay rdt = restrictedDelaunay(d, computeRestrictedVoronoi(d, sites));
        QCOMPARE(rdt.triangles.size(), std::size_t(2 * 60 - 4));
        // Closed and consistently oriented: every directed edge once, its reverse once.
        std::set<std::pair<int, int>> directed;
        for (const Triangle &t : rdt.triangles)
            for (int e = 0; e < 3; ++e)
                QVERIFY(directed.emplace(t[e], t[(e + 1) % 3]).second);
        for (const auto &[a, b] : directed)
            QVERIFY(directed.count({b, a}) == 1);
        QVERIFY(restrictedDelaunayQuality(rdt).meanQuality > 0.7);
    }
};

QTEST_GUILESS_MAIN(TestRestrictedVoronoi)
#include "test_restricted_voronoi.moc"
