// Output points of the remesher (thesis §4.4.2–4.4.3, Algorithm 4.2) on flat squares built in
// code: one point per restricted-cell component, at its centroid away from lines, on the line
// where a component touches one, and exactly at the corner a cell holds.
#include "remesh/output_points.h"

#include "remesh_test_models.h"
#include "voronoi/restricted_voronoi.h"
#include "voronoi/restriction_domain.h"

#include <QtTest>

#include <cmath>
#include <set>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

struct Stages {
    RestrictionDomain domain;
    RestrictedVoronoiDiagram rvd;
    CellComponents components;
    CellPoints points;
    SimplificationLedger ledger;
};

Stages run(const Model &model, const std::vector<Vec3> &sites, const CellPointsParams &params = {})
{
    Stages s;
    s.domain = makeRestrictionDomain(model);
    s.rvd = computeRestrictedVoronoi(s.domain, sites);
    s.components = computeCellComponents(s.domain, s.rvd);
    s.points = computeCellPoints(model, s.domain, s.rvd, s.components, params, s.ledger);
    return s;
}

// On a line of twoSquares(): the borders of [0, 2] × [0, 1] or the shared edge x = 1.
bool onALine(const Vec3 &p)
{
    return p.x() == 0.0 || p.x() == 1.0 || p.x() == 2.0 || p.y() == 0.0 || p.y() == 1.0;
}

} // namespace

class TestOutputPoints : public QObject {
    Q_OBJECT

private slots:
    // No line (a surface without topology): every cell is one component with one point, at the
    // centroid of its restricted cell — the site itself for a square cell around its centre.
    void onePointPerComponentAtTheCentroid()
    {
        Model m;
        m.surfaces = {flatSquare(7, 0.0, "square")};
        const int k = 4;
        const std::vector<Vec3> sites = gridSites(k, k, 1.0 / k);
        const Stages s = run(m, sites);
        QCOMPARE(int(s.components.cellSite.size()), k * k);
        QCOMPARE(int(s.points.points.size()), k * k);
        QCOMPARE(int(s.ledger.size()), 0);
        std::set<int> sitesWithPoint;
        double offCentroid = 0.0;
        for (std::size_t c = 0; c < s.components.cellSite.size(); ++c) {
            const int p = s.points.cellPoint[c];
            QVERIFY(p >= 0);
            const OutputPoint &point = s.points.points[std::size_t(p)];
            QCOMPARE(point.origin, PointOrigin::Surface);
            QCOMPARE(point.site, s.components.cellSite[c]);
            QVERIFY(point.lines.empty() && point.corners.empty());
            QCOMPARE(point.surfaces, std::vector<int>{0});
            // On the surface, inside the site's own square cell.
            const Vec3 d = point.position - sites[std::size_t(point.site)];
            QCOMPARE(point.position.z(), 0.0);
            QVERIFY(std::abs(d.x()) <= 0.5 / k && std::abs(d.y()) <= 0.5 / k);
            offCentroid = std::max(offCentroid, d.norm());
            sitesWithPoint.insert(point.site);
        }
        // The centroid of a square cell is its site (inside its facet, not snapped to an edge).
        QVERIFY2(offCentroid < 1e-12, qPrintable(QString::number(offCentroid)));
        QCOMPARE(int(sitesWithPoint.size()), k * k);
    }

    // A site whose cell covers two separate parts of the surface gets two components, hence two
    // points (the thesis's reason for working per component, Fig 4.4).
    void twoComponentsOfOneCellGiveTwoPoints()
    {
        Model m;
        m.surfaces = {flatSquare(4, 0.0, "a"), flatSquare(4, 3.0, "b")};
        // Site 0 sits between the squares and owns a strip of each (x in [0.75, 1] and [3, 3.25]);
        // sites 1 and 2 the rest.
        const std::vector<Vec3> sites{{2.0, 0.5, 0.0}, {-0.5, 0.5, 0.0}, {4.5, 0.5, 0.0}};
        const Stages s = run(m, sites);
        int ofSite0 = 0;
        for (int c : s.components.cellSite)
            ofSite0 += c == 0 ? 1 : 0;
        QCOMPARE(ofSite0, 2);
        QCOMPARE(int(s.components.cellSite.size()), 4);
        QCOMPARE(int(s.points.points.size()), 4);
        std::set<int> surfacesOfSite0;
        for (const OutputPoint &p : s.points.points)
            if (p.site == 0) {
                QCOMPARE(int(p.surfaces.size()), 1);
                surfacesOfSite0.insert(p.surfaces[0]);
                // Each at the centroid of its own part: in that square, not between them.
                QVERIFY(p.position.x() < 1.0 || p.position.x() > 3.0);
            }
        QCOMPARE(surfacesOfSite0, (std::set<int>{0, 1}));
    }

    // With lines and corners: the two cells holding the corners give Corner points exactly at
    // them; cells touching a line give points on that line; the others, centroid points off the
    // lines; every cell component has a point of its site.
    void cornersAndLines()
    {
        const Model m = twoSquares(7);
        QCOMPARE(int(m.corners.size()), 2);
        // Shifted so that no corner lies on a bisector.
        const std::vector<Vec3> sites = gridSites(8, 4, 0.25, 0.01);
        const Stages s = run(m, sites);
        std::set<std::pair<double, double>> cornerPositions;
        int corners = 0;
        for (const OutputPoint &p : s.points.points) {
            QVERIFY(p.site >= 0);
            QCOMPARE(p.position.z(), 0.0);
            switch (p.origin) {
            case PointOrigin::Corner:
                ++corners;
                QCOMPARE(int(p.corners.size()), 1);
                QCOMPARE(p.position, m.vertices[std::size_t(m.corners[p.corners[0]].vertex)]);
                cornerPositions.insert({p.position.x(), p.position.y()});
                break;
            case PointOrigin::Line:
                QVERIFY(!p.lines.empty());
                QVERIFY2(
                    onALine(p.position),
                    qPrintable(QStringLiteral("%1 %2").arg(p.position.x()).arg(p.position.y())));
                break;
            case PointOrigin::Surface:
                QVERIFY(p.lines.empty());
                QVERIFY(!onALine(p.position));
                break;
            }
        }
        QCOMPARE(corners, 2);
        QCOMPARE(cornerPositions, (std::set<std::pair<double, double>>{{1.0, 0.0}, {1.0, 1.0}}));
        // A component without line has its single centroid point; one with lines, none of that
        // kind (its points are on its lines).
        for (std::size_t c = 0; c < s.components.cellSite.size(); ++c) {
            const bool lineFree = s.components.cellLineComponents[c].empty();
            const int p = s.points.cellPoint[c];
            if (lineFree) {
                QVERIFY(p >= 0);
                QCOMPARE(s.points.points[std::size_t(p)].origin, PointOrigin::Surface);
            }
            bool hasPoint = false;
            for (const OutputPoint &q : s.points.points)
                hasPoint = hasPoint || q.site == s.components.cellSite[c];
            QVERIFY(hasPoint);
        }
        // Each line component with no corner got its own point, on its line.
        for (std::size_t l = 0; l < s.components.lineComponentSite.size(); ++l)
            if (s.components.lineComponentCorners[l].empty()) {
                const int p = s.points.lineComponentPoint[l];
                QVERIFY(p >= 0);
                QCOMPARE(s.points.points[std::size_t(p)].origin, PointOrigin::Line);
            }
    }

    // d_resolution merges points of one cell whose model parts are closer than it (Fig 4.7) and
    // records each merge: two parallel squares 0.05 apart, cells spanning both.
    void dResolutionMergesCloseParts()
    {
        Model m;
        m.surfaces = {flatSquare(4, 0.0, "low"), flatSquare(4, 0.0, "high")};
        for (Vec3 &v : m.surfaces[1].vertices)
            v.z() = 0.05;
        const std::vector<Vec3> sites = gridSites(2, 2, 0.5);
        const Stages apart = run(m, sites);
        QCOMPARE(int(apart.points.points.size()), 8); // one per cell and square
        CellPointsParams params;
        params.dResolution = 0.1;
        const Stages merged = run(m, sites, params);
        QCOMPARE(int(merged.points.points.size()), 4);
        QVERIFY(merged.ledger.size() >= 4);
        for (const OutputPoint &p : merged.points.points)
            QCOMPARE(p.surfaces, (std::vector<int>{0, 1}));
        // Below the gap, nothing merges.
        params.dResolution = 0.04;
        QCOMPARE(int(run(m, sites, params).points.points.size()), 8);
    }
};

QTEST_APPLESS_MAIN(TestOutputPoints)
#include "test_output_points.moc"
