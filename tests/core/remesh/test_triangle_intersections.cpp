// Exact intersection tests of output triangles and their repair (thesis §4.4.5).
#include "remesh/intersection_repair.h"
#include "remesh/triangle_intersections.h"

#include <Eigen/Geometry>
#include <QtTest>

using namespace stratamesh;

namespace {

OutputMesh grid(int n, double z, int surface)
{
    OutputMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            OutputPoint p;
            p.position = Vec3(i, j, z);
            p.surfaces.assign(1, surface);
            m.points.push_back(p);
        }
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, surface});
            m.triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, surface});
        }
    return m;
}

void append(OutputMesh &into, const OutputMesh &from)
{
    const int offset = static_cast<int>(into.points.size());
    into.points.insert(into.points.end(), from.points.begin(), from.points.end());
    for (OutputTriangle t : from.triangles) {
        for (int &v : t.v)
            v += offset;
        into.triangles.push_back(t);
    }
}

} // namespace

class TestTriangleIntersections : public QObject {
    Q_OBJECT
private slots:
    void pairs()
    {
        const std::vector<Vec3> p{
            Vec3(0, 0, 0),      Vec3(1, 0, 0),      Vec3(0, 1, 0),     // 0-2 flat
            Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1),  Vec3(0.3, 0.3, 1), // 3-5 crossing
            Vec3(5, 5, 5),      Vec3(6, 5, 5),      Vec3(5, 6, 5),     // 6-8 far away
            Vec3(1, 1, 0),      Vec3(0.5, -0.5, 0), Vec3(1, 1, 1)};
        QVERIFY(trianglesIntersect(p, {0, 1, 2}, {3, 4, 5}));
        QVERIFY(!trianglesIntersect(p, {0, 1, 2}, {6, 7, 8}));
        // Sharing an edge: unfolded (other side) no, folded onto the same side yes, bent no.
        QVERIFY(!trianglesIntersect(p, {0, 1, 2}, {1, 0, 10}));
        QVERIFY(trianglesIntersect(p, {0, 1, 2}, {1, 0, 9}));  // 9 on 2's side of edge 0-1: folded
        QVERIFY(!trianglesIntersect(p, {1, 2, 0}, {2, 1, 9})); // 9 across edge 1-2 from 0
        QVERIFY(!trianglesIntersect(p, {0, 1, 2}, {1, 2, 11}));
        // Sharing a vertex: a triangle through the other one.
        const std::vector<Vec3> q{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(1, 0.2, -1),
                                  Vec3(1, 0.2, 1)};
        QVERIFY(trianglesIntersect(q, {0, 1, 2}, {0, 3, 4}));
        const std::vector<Vec3> r{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(-1, -0.2, -1),
                                  Vec3(-1, -0.2, 1)};
        QVERIFY(!trianglesIntersect(r, {0, 1, 2}, {0, 3, 4}));
        // Folded: same edge, apexes on the same side in the same plane.
        const std::vector<Vec3> f{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, 2, 0)};
        QVERIFY(trianglesIntersect(f, {0, 1, 2}, {1, 0, 3}));
        QVERIFY(trianglesIntersect(f, {0, 1, 2}, {0, 1, 2}));
    }

    void crossingsAtStartComparesCounts()
    {
        OutputMesh m = grid(4, 0.0, 0);
        append(m, grid(4, 0.1, 1));
        m.points[12].position.z() = 0.3; // through the upper grid
        const EditableSoup start(m);
        const std::size_t pairs = soupIntersections(start).size();
        QVERIFY(pairs >= 6);
        CrossingsAtStart atStart(start);
        QVERIFY(!atStart.exceededBy(0));
        QVERIFY(!atStart.exceededBy(pairs));
        QVERIFY(atStart.exceededBy(pairs + 1));
        QVERIFY(!atStart.exceededBy(pairs - 1));
        // A start without crossings: any crossing is one more.
        const EditableSoup clean(grid(4, 0.0, 0));
        CrossingsAtStart none(clean);
        QVERIFY(!none.exceededBy(0));
        QVERIFY(none.exceededBy(1));
    }

    void twoGridsCrossedAndRepaired()
    {
        OutputMesh m = grid(4, 0.0, 0);
        append(m, grid(4, 0.1, 1));
        // An interior vertex of the lower grid pokes through the upper one.
        m.points[12].position.z() = 0.3; // (2, 2, 0)
        const std::vector<Vec3> pts = [&] {
            std::vector<Vec3> v;
            for (const OutputPoint &p : m.points)
                v.push_back(p.position);
            return v;
        }();
        std::vector<Triangle> tris;
        for (const OutputTriangle &t : m.triangles)
            tris.push_back(t.v);
        const auto pairs = findIntersectingTriangles(pts, tris);
        QVERIFY(pairs.size() >= 6);
        for (const auto &[a, b] : pairs)
            QVERIFY(m.triangles[a].surface != m.triangles[b].surface);

        EditableSoup soup(m);
        SimplificationLedger ledger;
        const IntersectionRepairResult r = repairIntersections(soup, Model{}, {}, ledger);
        QCOMPARE(r.found, static_cast<int>(pairs.size()));
        QCOMPARE(r.unresolved, 0);
        QVERIFY(ledger.empty());
        QVERIFY(soupIntersections(soup).empty());
        QVERIFY(soup.position(12).z() < 0.1);
    }

    void unresolvableIsReportedOrMerged()
    {
        // Two surfaces crossing everywhere: no flip nor move can fix it.
        OutputMesh m = grid(2, 0.0, 0);
        OutputMesh v = grid(2, 0.0, 1);
        for (OutputPoint &p : v.points)
            p.position = Vec3(p.position.x(), 1.0, p.position.y() - 1.0); // vertical, through y = 1
        append(m, v);

        EditableSoup kept(m);
        SimplificationLedger ledger;
        IntersectionRepairParams noMerge;
        noMerge.allowMerges = false;
        const IntersectionRepairResult r = repairIntersections(kept, Model{}, noMerge, ledger);
        QVERIFY(r.found > 0);
        QVERIFY(r.unresolved > 0);
        QCOMPARE(countKind(ledger, LedgerKind::IntersectionUnresolved), r.unresolved);
        QCOMPARE(countKind(ledger, LedgerKind::CloseFeatureMerge), 0);

        // Merging the points closer than the resolution undoes (some of) it, each merge recorded.
        EditableSoup merged(m);
        SimplificationLedger mergeLedger;
        const IntersectionRepairResult rm = repairIntersections(merged, Model{}, {}, mergeLedger);
        QCOMPARE(rm.found, r.found);
        QVERIFY(rm.unresolved < r.unresolved);
        QVERIFY(countKind(mergeLedger, LedgerKind::CloseFeatureMerge) > 0);
        QCOMPARE(static_cast<int>(soupIntersections(merged).size()), rm.unresolved);
    }
};

QTEST_GUILESS_MAIN(TestTriangleIntersections)
#include "test_triangle_intersections.moc"
