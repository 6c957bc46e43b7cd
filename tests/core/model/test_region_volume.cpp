// Region volumes with the Gocad side rule, and the box volume computed without sides.
#include "hand_models.h"

#include "common/error.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

bool close(double a, double b, double relative)
{
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b));
}

} // namespace

class TestRegionVolume : public QObject {
    Q_OBJECT

private slots:
    // Flat horizons at 1/3 and 2/3 of the height: three layers of exactly a third of the box.
    void flatLayersHaveTheirExactVolume()
    {
        LayeredBoxParams p;
        p.size = {300.0, 200.0, 90.0};
        p.horizons = 2;
        p.edgeLength = 25.0;
        const Model m = recoverTopology(layeredBox(p));
        const std::vector<double> v = regionVolumes(m);
        QCOMPARE(v.size(), std::size_t(3));
        for (double x : v)
            QVERIFY2(close(x, 300.0 * 200.0 * 30.0, 1e-12),
                     qPrintable(QString::number(x, 'g', 17)));
        QVERIFY(close(universeVolume(m), -300.0 * 200.0 * 90.0, 1e-12));
    }

    // Vertical fault at 0.4·x with throw 20 under one horizon at (90 − 20)/2 + 20 = 55:
    // west layers 55 and 35 thick over a width of 120, east ones 35 and 55 over 180.
    void faultBlocksHaveTheirExactVolume()
    {
        LayeredBoxParams p;
        p.size = {300.0, 200.0, 90.0};
        p.horizons = 1;
        p.fault = true;
        p.faultPosition = 0.4;
        p.faultThrow = 20.0;
        p.edgeLength = 30.0;
        const Model m = recoverTopology(layeredBox(p));
        const std::vector<double> v = regionVolumes(m);
        QCOMPARE(v.size(), std::size_t(4));
        const double expected[] = {120 * 200 * 55.0, 120 * 200 * 35.0, 180 * 200 * 35.0,
                                   180 * 200 * 55.0};
        for (int i = 0; i < 4; ++i)
            QVERIFY2(close(v[i], expected[i], 1e-12), qPrintable(QString::number(v[i], 'g', 17)));
    }

    void foldedFaultedBoxVolumesArePositiveAndSumToTheBox()
    {
        for (const Model &raw : {sampleModel(), [] {
                                     LayeredBoxParams p;
                                     p.horizons = 3;
                                     p.fault = true;
                                     p.faultDipDegrees = 50.0;
                                     p.faultThrow = 35.0;
                                     p.foldAmplitude = 70.0;
                                     p.thinLayerThickness = 4.0;
                                     p.edgeLength = 40.0;
                                     return layeredBox(p);
                                 }()}) {
            const Model m = recoverTopology(raw);
            double sum = 0.0;
            for (double v : regionVolumes(m)) {
                QVERIFY(v > 0.0);
                sum += v;
            }
            const double box = boxEnclosedVolume(m);
            QVERIFY2(
                close(sum, box, 1e-9),
                qPrintable(QStringLiteral("%1 vs %2").arg(sum, 0, 'g', 17).arg(box, 0, 'g', 17)));
            // The box is a cuboid whatever its patches: its volume is known without the mesh.
            QVERIFY(close(box, m.name == "sample" ? 1600.0 * 930.0 * 500.0 : 1000.0 * 600.0 * 400.0,
                          1e-12));
            QVERIFY(close(universeVolume(m), -sum, 1e-9));
        }
    }

    // Sides decide the sign: the same shell listed with the other sign has the opposite volume.
    void flippedSidesGiveNegativeVolume()
    {
        const Model m = recoverTopology(nestedSpheres({}));
        const std::vector<double> v = regionVolumes(m);
        QVERIFY(v[0] > 0.0 && v[1] > 0.0);
        const double ball = 4.0 / 3.0 * 3.14159265358979323846;
        QVERIFY(v[0] < ball && v[0] > 0.95 * ball); // inscribed icosphere
        QVERIFY(close(sidesVolume(m, {{0, true}}), -v[0], 1e-14));
        QVERIFY(close(enclosedVolume(m, {1}), v[0] + v[1], 1e-12));
        QVERIFY(close(enclosedVolume(m, {0, 1}), 2.0 * v[0] + v[1], 1e-12)); // two shells
        // A surface listed with both signs (inside the region) adds nothing.
        QVERIFY(close(sidesVolume(m, {{0, false}, {1, true}, {1, false}}), v[0], 1e-14));
    }

    // Independent of the sides: a shell with half of its triangles flipped has the same volume.
    void enclosedVolumeOrientsTheShellItself()
    {
        Model m = nestedSpheres({});
        const double before = enclosedVolume(recoverTopology(m), {0});
        for (std::size_t t = 0; t < m.surfaces[0].triangles.size(); t += 2)
            std::swap(m.surfaces[0].triangles[t][0], m.surfaces[0].triangles[t][1]);
        QVERIFY(close(enclosedVolume(recoverTopology(m), {0}), before, 1e-14));
    }

    void openShellsAreRejected()
    {
        const Model open = recoverTopology(modelOf({square("a")}));
        QVERIFY_THROWS_EXCEPTION(InputError, enclosedVolume(open, {0}));
        QVERIFY_THROWS_EXCEPTION(InputError, boxEnclosedVolume(open)); // no box at all
        QVERIFY_THROWS_EXCEPTION(InputError,
                                 enclosedVolume(modelOf({square("a")}), {0})); // no topology
    }

    // Far from the origin (Gocad coordinates like 1.6e6) the reference point keeps precision.
    void volumesStayAccurateFarFromTheOrigin()
    {
        Model m = layeredBox([] {
            LayeredBoxParams p;
            p.size = {1600.0, 930.0, 500.0};
            p.horizons = 2;
            p.edgeLength = 60.0;
            return p;
        }());
        for (Surface &s : m.surfaces)
            for (Vec3 &x : s.vertices)
                x += Vec3(1.6e6, 2.3e6, -3000.0);
        m = recoverTopology(std::move(m));
        for (double v : regionVolumes(m))
            QVERIFY(close(v, 1600.0 * 930.0 * 500.0 / 3.0, 1e-9));
    }
};

QTEST_GUILESS_MAIN(TestRegionVolume)
#include "test_region_volume.moc"
