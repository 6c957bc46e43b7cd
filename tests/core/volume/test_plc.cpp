// The PLC of a model and its TetGen .poly file: seeds strictly inside their regions, facets on
// the merged points with surface markers, and Debian's tetgen executable reading the file.
#include "common/error.h"
#include "tetgen_test_models.h"
#include "volume/plc.h"
#include "volume/region_winding.h"
#include "volume/tetgen_poly_writer.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>
#include <QtTest>

#include <set>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

// Tet attributes of a TetGen .ele file (one attribute column).
std::multiset<int> eleAttributes(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QTextStream in(&f);
    int count = 0, corners = 0, attributes = 0;
    in >> count >> corners >> attributes;
    std::multiset<int> result;
    for (int i = 0; i < count && attributes == 1; ++i) {
        int index, a, b, c, d;
        double attribute;
        in >> index >> a >> b >> c >> d >> attribute;
        result.insert(static_cast<int>(attribute));
    }
    return result;
}

} // namespace

class TestPlc : public QObject {
    Q_OBJECT

private slots:
    void seedsAreInsideTheirRegions()
    {
        const Model m = twoRegionBox();
        QCOMPARE(m.regions.size(), std::size_t(2));
        const Plc plc = buildPlc(m);
        QCOMPARE(plc.regions.size(), std::size_t(2));
        for (int r = 0; r < 2; ++r) {
            const PlcRegion &region = plc.regions[r];
            QCOMPARE(region.attribute, r + 1);
            QCOMPARE(region.name, m.regions[r].name);
            QVERIFY(region.clearance > 1.0);
            QVERIFY(std::abs(regionWindingNumber(m, r, region.seed) - 1.0) < 1e-9);
            QVERIFY(std::abs(regionWindingNumber(m, 1 - r, region.seed)) < 1e-9);
            QCOMPARE(locateRegion(m, region.seed), r);
            QVERIFY(region.seed.x() > 0 && region.seed.x() < 1000);
            QVERIFY(region.seed.z() > 0 && region.seed.z() < 400);
        }
    }

    void facetsUseMergedPointsAndSurfaceMarkers()
    {
        const Model m = twoRegionBox();
        const Plc plc = buildPlc(m);
        QCOMPARE(plc.points.size(), m.vertices.size());
        QCOMPARE(plc.facets.size(), m.triangleCount());
        QCOMPARE(plc.facetMarkers.size(), plc.facets.size());
        std::size_t f = 0;
        for (int s = 0; s < static_cast<int>(m.surfaces.size()); ++s)
            for (const Triangle &t : m.surfaces[s].triangles) {
                QCOMPARE(plc.facetMarkers[f], s + 1);
                for (int k = 0; k < 3; ++k)
                    QCOMPARE(plc.points[plc.facets[f][k]], m.surfaces[s].vertices[t[k]]);
                ++f;
            }
        // Without topology it is recovered on a copy: same PLC.
        Model raw = m;
        raw.vertices.clear();
        raw.surfaceVertexToGlobal.clear();
        QCOMPARE(buildPlc(raw).facets, plc.facets);
    }

    // A point no triangle uses (the centre a re-triangulation dropped), lying on a facet: TetGen
    // throws on it, so the PLC leaves it out and keeps the other points in their order.
    void freePointsAreLeftOut()
    {
        Model m = twoRegionBox();
        const int h = horizonOf(m);
        Surface &horizon = m.surfaces[h];
        const Triangle &t = horizon.triangles.front();
        horizon.vertices.push_back(
            (horizon.vertices[t[0]] + horizon.vertices[t[1]] + horizon.vertices[t[2]]) / 3.0);
        m = recoverTopology(m);
        const Plc plc = buildPlc(m);
        QCOMPARE(plc.points.size() + 1, m.vertices.size());
        const Plc clean = buildPlc(twoRegionBox());
        QCOMPARE(plc.points, clean.points);
        QCOMPARE(plc.facets, clean.facets);
    }

    void badModelsAreInputErrors()
    {
        QVERIFY_THROWS_EXCEPTION(InputError, buildPlc(Model{}));
        // A region whose only side is open has no inside.
        Model m = twoRegionBox();
        m.regions[0].boundaries.resize(1);
        QVERIFY_THROWS_EXCEPTION(InputError, buildPlc(m));
        // A triangle collapsed onto two points.
        Model collapsed = twoRegionBox();
        Surface &s = collapsed.surfaces[0];
        s.triangles[0][1] = s.triangles[0][0];
        QVERIFY_THROWS_EXCEPTION(InputError, buildPlc(collapsed));
    }

    void tetgenReadsThePolyFile()
    {
        const QString tetgen = QStandardPaths::findExecutable("tetgen");
        if (tetgen.isEmpty())
            QSKIP("the tetgen executable is not installed (Debian package tetgen)");
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString poly = dir.filePath("box.poly");
        writeTetgenPoly(buildPlc(twoRegionBox()), poly.toStdString());

        QProcess mesh;
        mesh.start(tetgen, {"-pq1.414AYQ", poly});
        QVERIFY(mesh.waitForFinished(60000));
        QCOMPARE(mesh.exitStatus(), QProcess::NormalExit);
        QCOMPARE(mesh.exitCode(), 0);
        const std::multiset<int> attributes = eleAttributes(dir.filePath("box.1.ele"));
        QVERIFY(attributes.size() > 100);
        QVERIFY(attributes.count(1) > 0);
        QVERIFY(attributes.count(2) > 0);
        QCOMPARE(attributes.count(1) + attributes.count(2), attributes.size());

        QProcess detect;
        detect.start(tetgen, {"-d", poly});
        QVERIFY(detect.waitForFinished(60000));
        QCOMPARE(detect.exitCode(), 0);
        const QByteArray report = detect.readAllStandardOutput();
        QVERIFY2(report.contains("No faces are intersecting"), report.constData());
    }
};

QTEST_GUILESS_MAIN(TestPlc)
#include "test_plc.moc"
