// Each validity check on a small hand-built model that breaks it, and valid models reported valid.
#include "hand_models.h"

#include "common/error.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <cmath>
#include <map>

using namespace stratamesh;
using namespace stratamesh::test;
namespace check = stratamesh::validity_check;

Q_DECLARE_METATYPE(stratamesh::Vec3)

namespace {

QString summary(const ValidityReport &r)
{
    QStringList parts;
    for (const auto &[name, n] : r.counts)
        parts << QStringLiteral("%1=%2").arg(QString::fromStdString(name)).arg(n);
    for (std::size_t i = 0; i < r.problems.size() && i < 3; ++i)
        parts << QString::fromStdString(r.problems[i].message);
    return parts.join(QStringLiteral("; "));
}

Surface triangle(const std::string &name, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return makeSurface(name, {a, b, c}, {{0, 1, 2}});
}

LayeredBoxParams smallBox()
{
    LayeredBoxParams p;
    p.size = {300.0, 200.0, 100.0};
    p.horizons = 1;
    p.edgeLength = 50.0;
    return p;
}

// Removes surface s and every side naming it (indices above s shift down).
Model withoutSurface(Model m, int s)
{
    m.surfaces.erase(m.surfaces.begin() + s);
    auto fix = [s](std::vector<RegionSide> &sides) {
        std::vector<RegionSide> kept;
        for (RegionSide side : sides)
            if (side.surface != s) {
                side.surface -= side.surface > s ? 1 : 0;
                kept.push_back(side);
            }
        sides = kept;
    };
    for (Region &r : m.regions)
        fix(r.boundaries);
    fix(m.universe);
    return m;
}

// A tetrahedron with outward normals, its right angle at o.
Surface tetrahedron(const std::string &name, double size, const Vec3 &o)
{
    return makeSurface(name, {o, o + Vec3(size, 0, 0), o + Vec3(0, size, 0), o + Vec3(0, 0, size)},
                       {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

} // namespace

class TestValidity : public QObject {
    Q_OBJECT

private slots:
    void syntheticModelsAreValid_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("sample") << 0;
        QTest::newRow("box, one horizon") << 1;
        QTest::newRow("dipping fault, thin layer, fold") << 2;
        QTest::newRow("nested spheres") << 3;
        QTest::newRow("nested spheres without regions") << 4;
    }
    void syntheticModelsAreValid()
    {
        QFETCH(int, which);
        Model m;
        if (which == 0) {
            m = sampleModel();
        } else if (which == 1) {
            m = layeredBox(smallBox());
        } else if (which == 2) {
            LayeredBoxParams p;
            p.horizons = 3;
            p.fault = true;
            p.faultDipDegrees = 45.0;
            p.faultThrow = 30.0;
            p.foldAmplitude = 60.0;
            p.thinLayerThickness = 3.0;
            p.edgeLength = 45.0;
            m = layeredBox(p);
        } else {
            NestedSpheresParams p;
            p.withRegions = which == 3;
            m = nestedSpheres(p);
        }
        const ValidityReport r = checkValidity(recoverTopology(m));
        QVERIFY2(r.valid, qPrintable(summary(r)));
        QVERIFY(r.problems.empty());
        QVERIFY(r.counts.empty());
    }

    void notSealed()
    {
        Surface far = square("b", 5.0);
        const ValidityReport r = checkValidity(modelOf({square("a"), far}));
        QVERIFY(!r.valid);
        QCOMPARE(r.count(check::notSealed), std::size_t(2));
        QCOMPARE(r.problems.front().check, std::string(check::notSealed));
        QCOMPARE(r.problems.front().entities.front(), std::string("a"));
    }

    // A box with one patch missing: the neighbouring patches' borders touch nothing.
    void boxWithAHoleIsNotSealed()
    {
        const Model full = layeredBox(smallBox());
        const ValidityReport r =
            checkValidity(withoutSurface(full, static_cast<int>(full.surfaces.size()) - 1));
        QVERIFY(r.count(check::notSealed) >= 1);
        QVERIFY(r.count(check::regionBoundary) >= 1); // the region lost part of its boundary
    }

    // A surface hanging inside one region (listed with both signs there) may have free borders,
    // like a dangling fault; unlisted, the same surface is reported.
    void freeBorderInsideARegionIsAllowed()
    {
        Model m = nestedSpheres({});
        m.surfaces.push_back(square("hanging", 0.1));
        for (Vec3 &p : m.surfaces.back().vertices)
            p = 0.5 * p;
        Model listed = m;
        listed.regions[0].boundaries.push_back({2, true});
        listed.regions[0].boundaries.push_back({2, false});
        const ValidityReport ok = checkValidity(listed);
        QVERIFY2(ok.valid, qPrintable(summary(ok)));
        QCOMPARE(checkValidity(m).count(check::notSealed), std::size_t(1));
    }

    void nonManifoldEdge()
    {
        const Surface fan =
            makeSurface("fan", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                        {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
        const ValidityReport r = checkValidity(modelOf({fan}));
        QCOMPARE(r.count(check::nonManifoldEdge), std::size_t(1));
        QCOMPARE(r.count(check::notSealed),
                 std::size_t(3)); // three border lines between the edge's ends
    }

    void degenerateTriangles()
    {
        const Surface repeated =
            makeSurface("repeated", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 1}});
        const Surface collinear = triangle("collinear", {0, 0, 5}, {1, 1, 5}, {3, 3, 5});
        const Surface samePlace =
            makeSurface("samePlace", {{0, 0, 9}, {1, 0, 9}, {0, 0, 9}}, {{0, 1, 2}});
        const ValidityReport r = checkValidity(modelOf({repeated, collinear, samePlace}));
        QCOMPARE(r.count(check::degenerateTriangle), std::size_t(3));
        QCOMPARE(r.count(check::surfaceIntersection),
                 std::size_t(0)); // degenerate ones are skipped
        // A nearly flat but non-degenerate triangle is fine.
        const Surface needle = triangle("needle", {0, 0, 0}, {1, 0, 0}, {2, 1e-12, 0});
        QCOMPARE(checkValidity(modelOf({needle})).count(check::degenerateTriangle), std::size_t(0));
    }

    void duplicateTriangles()
    {
        const ValidityReport across = checkValidity(modelOf({square("a"), square("b")}));
        QCOMPARE(across.count(check::duplicateTriangle), std::size_t(2));
        const Surface twice =
            makeSurface("twice", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {1, 2, 0}});
        QCOMPARE(checkValidity(modelOf({twice})).count(check::duplicateTriangle), std::size_t(1));
    }

    // The remesh of modelA2 at 1000 sites had two copies of a triangle 1e-12 apart: distinct for
    // the exact checks, one point for TetGen, which then aborted on "two duplicated facets".
    void closeVerticesAreWhatTetGenMerges()
    {
        const Surface a = makeSurface("a", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        const Surface b = makeSurface("b", {{0, 0, 1e-12}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        const ValidityReport r = checkValidity(modelOf({a, b}));
        QCOMPARE(r.count(check::duplicateTriangle), std::size_t(0));
        QCOMPARE(r.count(check::closeVertices), std::size_t(1));
        QVERIFY(!r.valid);
        const ValidityProblem &p = r.problems.front();
        QCOMPARE(p.check, std::string(check::closeVertices));
        QCOMPARE(p.entities, (std::vector<std::string>{"a", "b"}));
        // 1e-6 of the diagonal is far above the merge tolerance: fine.
        const Surface c = makeSurface("c", {{0, 0, 1e-6}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        QCOMPARE(checkValidity(modelOf({a, c})).count(check::closeVertices), std::size_t(0));
    }

    void inconsistentOrientation()
    {
        const Surface flipped = makeSurface("flipped", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                            {{0, 1, 2}, {0, 3, 2}});
        const ValidityReport r = checkValidity(modelOf({flipped}));
        QCOMPARE(r.count(check::inconsistentOrientation), std::size_t(1));
        QCOMPARE(checkValidity(modelOf({square("fine")})).count(check::inconsistentOrientation),
                 std::size_t(0));
    }

    void crossingSurfacesIntersect()
    {
        const Surface wall =
            makeSurface("wall", {{0.5, -1, -1}, {0.5, 2, -1}, {0.5, 2, 1}, {0.5, -1, 1}},
                        {{0, 1, 2}, {0, 2, 3}});
        const ValidityReport r = checkValidity(modelOf({square("floor"), wall}));
        QVERIFY(r.count(check::surfaceIntersection) >= 1);
        for (const ValidityProblem &p : r.problems)
            if (p.check == check::surfaceIntersection) {
                QCOMPARE(p.entities.size(), std::size_t(2));
                QVERIFY(std::abs(p.position.x() - 0.5) < 1e-12); // on both planes
                QVERIFY(std::abs(p.position.z()) < 1e-12);
            }
    }

    // The pocket repair's check for edits cleared by trianglesMeetOthers: the same report but for
    // the intersections.
    void everyCheckButTheIntersections()
    {
        const Surface wall =
            makeSurface("wall", {{0.5, -1, -1}, {0.5, 2, -1}, {0.5, 2, 1}, {0.5, -1, 1}},
                        {{0, 1, 2}, {0, 2, 3}});
        const Surface flipped = makeSurface("flipped", {{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}},
                                            {{0, 1, 2}, {0, 3, 2}});
        const Model m = modelOf({square("floor"), wall, flipped});
        const ValidityReport all = checkValidity(m);
        const ValidityReport rest = checkValidityExceptIntersections(m);
        QVERIFY(all.count(check::surfaceIntersection) >= 1);
        QCOMPARE(rest.count(check::surfaceIntersection), std::size_t(0));
        QCOMPARE(rest.count(check::inconsistentOrientation), std::size_t(1));
        std::map<std::string, std::size_t> expected = all.counts;
        expected.erase(check::surfaceIntersection);
        QCOMPARE(rest.counts, expected);
        QVERIFY(!rest.valid);
    }

    // Exact decisions for triangles sharing a vertex or an edge.
    void sharedVertexAndEdgeCases_data()
    {
        QTest::addColumn<Vec3>("c");
        QTest::addColumn<Vec3>("d");
        QTest::addColumn<bool>("intersects");
        // First triangle: (0,0,0), (2,0,0), (0,2,0). Second: (0,0,0), c, d — or (0,0,0), (2,0,0),
        // d.
        QTest::newRow("vertex, opposite quadrant") << Vec3(-1, 0, 0) << Vec3(0, -1, 0) << false;
        QTest::newRow("vertex, coplanar inside") << Vec3(1, 0.2, 0) << Vec3(0.2, 1, 0) << true;
        QTest::newRow("vertex, coplanar along an edge") << Vec3(1, 0, 0) << Vec3(1, -1, 0) << true;
        QTest::newRow("vertex, piercing") << Vec3(1, 1, -1) << Vec3(1, 1, 1) << true;
        QTest::newRow("vertex, above") << Vec3(1, 0, 1) << Vec3(0, 1, 1) << false;
        QTest::newRow("edge, coplanar fold") << Vec3(2, 0, 0) << Vec3(0.5, 0.5, 0) << true;
        QTest::newRow("edge, coplanar other side") << Vec3(2, 0, 0) << Vec3(0.5, -0.5, 0) << false;
        QTest::newRow("edge, dihedral") << Vec3(2, 0, 0) << Vec3(0.5, 0.5, 1e-9) << false;
    }
    void sharedVertexAndEdgeCases()
    {
        QFETCH(Vec3, c);
        QFETCH(Vec3, d);
        QFETCH(bool, intersects);
        const Surface first = triangle("first", {0, 0, 0}, {2, 0, 0}, {0, 2, 0});
        const Surface second = triangle("second", {0, 0, 0}, c, d);
        const ValidityReport r = checkValidity(modelOf({first, second}));
        QCOMPARE(r.count(check::surfaceIntersection) > 0, intersects);
        // The same decision from either triangle alone (what the pocket repair asks).
        const Model m = recoverTopology(modelOf({first, second}));
        QCOMPARE(trianglesMeetOthers(m, 0, {0}), intersects);
        QCOMPARE(trianglesMeetOthers(m, 1, {0}), intersects);
        QVERIFY(!trianglesMeetOthers(m, 1, {}));
    }

    // On a model with many triangles, the triangles trianglesMeetOthers flags are exactly those
    // of the pairs checkValidity reports.
    void meetingTrianglesAreTheReportedOnes()
    {
        const Surface wall =
            makeSurface("wall", {{0.5, -1, -1}, {0.5, 2, -1}, {0.5, 2, 1}, {0.5, -1, 1}},
                        {{0, 1, 2}, {0, 2, 3}});
        const Model m = recoverTopology(modelOf({square("floor"), square("far", 5.0), wall}));
        const ValidityReport r = checkValidity(m);
        QVERIFY(r.count(check::surfaceIntersection) >= 1);
        for (std::size_t s = 0; s < m.surfaces.size(); ++s)
            for (std::size_t t = 0; t < m.surfaces[s].triangles.size(); ++t) {
                bool reported = false;
                const std::string tag =
                    "triangle " + std::to_string(t) + " of " + m.surfaces[s].name;
                for (const ValidityProblem &p : r.problems)
                    reported = reported
                               || (p.check == check::surfaceIntersection
                                   && (p.message.find(tag + " ") != std::string::npos));
                QCOMPARE(trianglesMeetOthers(m, int(s), {int(t)}), reported);
            }
    }

    // A vertex of one surface on the middle of another's edge (a T-junction) is not conformal.
    void tJunctionIntersects()
    {
        const Surface below = triangle("below", {0.5, 0, 0}, {1, -1, 0}, {0, -1, 0});
        const ValidityReport r = checkValidity(modelOf({square("a"), below}));
        QCOMPARE(r.count(check::surfaceIntersection), std::size_t(1));
    }

    // Two triangles of a remeshed box face and a fault: an edge of one lies in the other's plane.
    // CGAL 5.5's construction of their intersection raises SIGFPE; the report must still say
    // where they meet, on both triangles.
    void edgeInTheOtherPlaneIsReportedWithoutCrashing()
    {
        const Vec3 f0(8049.6775117088682, -3279.8963082757773, 1009.9222794748259),
            f1(8199.3095703125, -3582.5927734375, 979.3951416015625),
            f2(7607.73681640625, -3582.5927734375, 1096.326171875);
        const Vec3 g0(7667.48681640625, -3582.5927734375, 1084.5301513671875),
            g1(8199.677734375, -3582.5927734375, 779.33453369140625),
            g2(7608.26220703125, -3582.5927734375, 896.2364501953125);
        const ValidityReport r =
            checkValidity(modelOf({triangle("fault", f0, f1, f2), triangle("box", g0, g1, g2)}));
        QCOMPARE(r.count(check::surfaceIntersection), std::size_t(1));
        for (const ValidityProblem &p : r.problems)
            if (p.check == check::surfaceIntersection) {
                QVERIFY(std::abs(p.position.y() - g0.y()) < 1e-9); // in the box face's plane
                const Vec3 n = (f1 - f0).cross(f2 - f0).normalized();
                QVERIFY(std::abs(n.dot(p.position - f0)) < 1e-6); // and in the fault triangle's
            }
    }

    void selfIntersectionOfOneSurface()
    {
        const Surface folded = makeSurface(
            "folded", {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}},
            {{0, 1, 2}, {3, 4, 5}});
        const ValidityReport r = checkValidity(modelOf({folded}));
        QCOMPARE(r.count(check::surfaceIntersection), std::size_t(1));
        QCOMPARE(r.problems.back().entities, std::vector<std::string>{"folded"});
    }

    void regionWithAFlippedSide()
    {
        Model m = layeredBox(smallBox());
        for (RegionSide &side : m.regions[0].boundaries)
            if (m.surfaces[side.surface].type == FeatureType::Horizon)
                side.positive = !side.positive;
        const ValidityReport r = checkValidity(m);
        QVERIFY(r.count(check::regionBoundary)
                >= 1); // inconsistent in region 0 and side claimed twice
        bool inconsistent = false;
        for (const ValidityProblem &p : r.problems)
            inconsistent = inconsistent
                           || (p.check == check::regionBoundary && p.entities.front() == "layer1"
                               && p.message.find("inconsistent") != std::string::npos);
        QVERIFY2(inconsistent, qPrintable(summary(r)));
    }

    void regionMissingASurface()
    {
        Model m = layeredBox(smallBox());
        m.regions[1].boundaries.pop_back();
        const ValidityReport r = checkValidity(m);
        bool open = false;
        for (const ValidityProblem &p : r.problems)
            open = open || p.message.find("not closed") != std::string::npos;
        QVERIFY2(open, qPrintable(summary(r)));
    }

    // A closed, consistent shell listed with the wrong signs has a negative volume.
    void regionSidesAgainstTheNormals()
    {
        Model m = nestedSpheres({});
        m.regions = {{"inner", {{0, true}}}};
        m.universe.clear();
        const ValidityReport r = checkValidity(m);
        QCOMPARE(r.count(check::regionBoundary), std::size_t(1));
        QVERIFY(r.problems.front().message.find("volume") != std::string::npos);
    }

    void sideClaimedByTwoRegions()
    {
        Model m = nestedSpheres({});
        m.regions.push_back({"copy", {{0, false}}});
        const ValidityReport r = checkValidity(m);
        QCOMPARE(r.count(check::regionBoundary), std::size_t(1));
        QCOMPARE(r.problems.front().entities.size(), std::size_t(3));
    }

    // The same with a pocket of 1.3 m³ in a model 35 km across: a remesh of modelA5 left one of
    // 5.1 m³ that TetGen meshed as a region without a seed, below the old limit of 1e-12 ×
    // diagonal³ (42 m³ here). Each shell is measured against its own size.
    void tinyPocketInALargeModel()
    {
        Model m = modelOf({tetrahedron("big", 20000.0, Vec3::Zero()),
                           tetrahedron("small", 2.0, Vec3(20000.0, 5000.0, 0.0))});
        m.regions = {{"inside", {{0, false}, {1, false}}}};
        m.universe = {{0, true}, {1, true}};
        const ValidityReport r = checkValidity(m);
        QCOMPARE(r.count(check::regionPocket), std::size_t(1));
        QVERIFY2(r.problems.front().message.find("1.33") != std::string::npos,
                 r.problems.front().message.c_str());
    }

    // One region on the inside of two tetrahedra: every side closed, balanced and of positive
    // volume, yet the region is in two pieces and one seed would leave the smaller one empty.
    void regionInTwoPiecesHasAPocket()
    {
        Model m = modelOf({tetrahedron("big", 1.0, Vec3::Zero()),
                           tetrahedron("small", 0.5, Vec3(5.0, 0.0, 0.0))});
        m.regions = {{"inside", {{0, false}, {1, false}}}};
        m.universe = {{0, true}, {1, true}};
        const ValidityReport r = checkValidity(m);
        QCOMPARE(r.count(check::regionPocket), std::size_t(1));
        QCOMPARE(r.counts.size(), std::size_t(1));
        const ValidityProblem &p = r.problems.front();
        QCOMPARE(p.entities, (std::vector<std::string>{"inside", "small"}));
        QVERIFY((p.position - Vec3(5.125, 0.125, 0.125)).norm() < 0.1);

        // The same shells as a region with a cavity (one inside the other) are one piece.
        m.surfaces[1] = tetrahedron("small", 0.2, Vec3(0.1, 0.1, 0.1));
        m.regions = {{"shell", {{0, false}, {1, true}}}, {"core", {{1, false}}}};
        m.universe = {{0, true}};
        const ValidityReport nested = checkValidity(m);
        QVERIFY2(nested.valid, qPrintable(summary(nested)));
    }

    void listsAreCappedButCountsAreNot()
    {
        Surface bad = makeSurface("bad", {{0, 0, 0}, {1, 0, 0}}, {});
        for (int i = 0; i < 150; ++i)
            bad.triangles.push_back({0, 1, 1});
        const ValidityReport r = checkValidity(modelOf({bad}));
        QCOMPARE(r.count(check::degenerateTriangle), std::size_t(150));
        std::size_t listed = 0;
        for (const ValidityProblem &p : r.problems)
            listed += p.check == check::degenerateTriangle ? 1 : 0;
        QCOMPARE(listed, ValidityReport::kMaxListedPerCheck);
    }

    void topologyIsRecoveredWhenMissing()
    {
        const Model raw = withoutSurface(layeredBox(smallBox()), 0);
        QVERIFY(!raw.hasTopology());
        const ValidityReport a = checkValidity(raw);
        const ValidityReport b = checkValidity(recoverTopology(raw));
        QVERIFY(!a.valid);
        QCOMPARE(a.counts, b.counts);
    }

    void cancelStops()
    {
        Progress progress;
        progress.cancel();
        QVERIFY_THROWS_EXCEPTION(Cancelled, checkValidity(sampleModel(), progress));
    }
};

QTEST_GUILESS_MAIN(TestValidity)
#include "test_validity.moc"
