// The code-built fixtures: parameters checked, shapes as documented, sample model size.
#include "common/error.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"

#include <QtTest>

#include <Eigen/Geometry>

#include <cmath>
#include <set>

using namespace stratamesh;

class TestSyntheticModels : public QObject {
    Q_OBJECT

private slots:
    void impossibleParametersAreRejected()
    {
        auto rejects = [](auto change) {
            LayeredBoxParams p;
            p.horizons = 2;
            change(p);
            try {
                layeredBox(p);
            } catch (const InputError &) {
                return true;
            }
            return false;
        };
        QVERIFY(rejects([](LayeredBoxParams &p) { p.edgeLength = 0.0; }));
        QVERIFY(rejects([](LayeredBoxParams &p) { p.size.z() = -1.0; }));
        QVERIFY(
            rejects([](LayeredBoxParams &p) { p.foldAmplitude = 400.0; })); // fold fills the box
        QVERIFY(rejects([](LayeredBoxParams &p) {
            p.fault = true;
            p.faultThrow = 450.0;
        })); // throw too
        QVERIFY(rejects([](LayeredBoxParams &p) {
            p.fault = true;
            p.faultDipDegrees = 10.0;
        }));                                                                // leaves the box
        QVERIFY(rejects([](LayeredBoxParams &p) { p.faultThrow = 10.0; })); // throw, no fault
        QVERIFY(rejects(
            [](LayeredBoxParams &p) { p.thinLayerThickness = 200.0; })); // thicker than a layer
        QVERIFY(!rejects([](LayeredBoxParams &p) {
            p.fault = true;
            p.faultDipDegrees = 60.0;
            p.faultThrow = 50.0;
        }));
        NestedSpheresParams s;
        s.outerRadius = 0.5;
        QVERIFY_THROWS_EXCEPTION(InputError, nestedSpheres(s));
        s.outerRadius = 2.0;
        s.middleRadius = 2.5; // outside the outer sphere
        QVERIFY_THROWS_EXCEPTION(InputError, nestedSpheres(s));
    }

    // All vertices inside the box, horizons follow z = c + A sin(π y / Ly) exactly at the grid.
    void layeredBoxGeometry()
    {
        LayeredBoxParams p;
        p.horizons = 2;
        p.foldAmplitude = 50.0;
        p.fault = true;
        p.faultDipDegrees = 60.0;
        p.faultThrow = 40.0;
        const Model m = layeredBox(p);
        int horizons = 0;
        for (const Surface &s : m.surfaces) {
            for (const Vec3 &v : s.vertices)
                QVERIFY(v.x() >= 0.0 && v.x() <= p.size.x() && v.y() >= 0.0 && v.y() <= p.size.y()
                        && v.z() >= 0.0 && v.z() <= p.size.z());
            if (s.type != FeatureType::Horizon)
                continue;
            ++horizons;
            // One horizon patch: z − fold(y) is one constant.
            const double c =
                s.vertices[0].z()
                - 50.0 * std::sin(3.14159265358979323846 * s.vertices[0].y() / p.size.y());
            for (const Vec3 &v : s.vertices)
                QVERIFY(std::abs(v.z()
                                 - 50.0 * std::sin(3.14159265358979323846 * v.y() / p.size.y()) - c)
                        < 1e-9);
        }
        QCOMPARE(horizons, 4); // two horizons in two blocks
        QCOMPARE(m.regions.size(), std::size_t(6));
        QCOMPARE(m.layers.size(), std::size_t(3));
    }

    void thinLayerAddsOneHorizon()
    {
        LayeredBoxParams p;
        p.horizons = 2;
        p.thinLayerThickness = 2.0;
        const Model m = recoverTopology(layeredBox(p));
        const ModelCounts c = countEntities(m);
        QCOMPARE(c.withoutBox.surfaces, 3);
        QCOMPARE(c.all.regions, 4);
        double thinnest = 1e300;
        for (std::size_t a = 0; a < m.surfaces.size(); ++a)
            for (std::size_t b = a + 1; b < m.surfaces.size(); ++b)
                if (m.surfaces[a].type == FeatureType::Horizon
                    && m.surfaces[b].type == FeatureType::Horizon)
                    thinnest = std::min(thinnest, std::abs(m.surfaces[a].vertices[0].z()
                                                           - m.surfaces[b].vertices[0].z()));
        QVERIFY(std::abs(thinnest - 2.0) < 1e-9);
    }

    void sampleModelIsAFewThousandTriangles()
    {
        const Model m = recoverTopology(sampleModel());
        QVERIFY(m.triangleCount() >= 2000 && m.triangleCount() <= 10000);
        const ModelCounts c = countEntities(m);
        QCOMPARE(c.withoutBox.regions, 8);   // four layers on each side of the fault
        QCOMPARE(c.withoutBox.surfaces, 13); // 3 + 3 horizon patches, 7 fault patches
        QCOMPARE(c.withoutBox.lines, 6);     // the horizon cutoffs on the fault
    }

    // Fault networks: n low-dip faults cut every horizon into n + 1 pieces; the model is valid and
    // its regions fill the box exactly.
    void faultNetworksAreValidAndFillTheBox_data()
    {
        QTest::addColumn<int>("faults");
        QTest::addColumn<double>("dip");
        QTest::newRow("3 faults 30°") << 3 << 30.0;
        QTest::newRow("5 faults 20°") << 5 << 20.0;
        QTest::newRow("10 faults 40°") << 10 << 40.0;
    }

    void faultNetworksAreValidAndFillTheBox()
    {
        QFETCH(int, faults);
        QFETCH(double, dip);
        const int horizons = 3;
        const Model m = recoverTopology(faultNetworkBox(faults, dip, horizons, 20.0, 60.0));
        const ValidityReport v = checkValidity(m);
        QVERIFY2(v.valid, v.problems.empty() ? "" : v.problems.front().message.c_str());
        const ModelCounts c = countEntities(m);
        QCOMPARE(c.all.regions, (faults + 1) * (horizons + 1));
        int horizonPieces = 0, faultFeatures = 0;
        std::set<std::string> features;
        for (const Surface &s : m.surfaces) {
            horizonPieces += s.type == FeatureType::Horizon ? 1 : 0;
            if (s.type == FeatureType::Fault && features.insert(s.featureName).second)
                ++faultFeatures;
        }
        QCOMPARE(horizonPieces, (faults + 1) * horizons);
        QCOMPARE(faultFeatures, faults);
        // Every horizon meets every fault on each side: two cutoff lines per horizon and fault.
        QVERIFY(c.withoutBox.lines >= 2 * faults * horizons);
        double volume = 0.0;
        for (double r : regionVolumes(m)) {
            QVERIFY(r > 0.0);
            volume += r;
        }
        const Vec3 lo = m.vertices.front(), size = [&] {
            Vec3 a = lo, b = lo;
            for (const Vec3 &p : m.vertices) {
                a = a.cwiseMin(p);
                b = b.cwiseMax(p);
            }
            return Vec3(b - a);
        }();
        QVERIFY(std::abs(volume - size.prod()) < 1e-9 * size.prod());
    }

    void spheresAreClosedAndOutward()
    {
        NestedSpheresParams p;
        p.subdivisions = 2;
        p.innerRadius = 3.0;
        p.outerRadius = 5.0;
        p.centre = {10.0, 0.0, -2.0};
        const Model m = nestedSpheres(p);
        QCOMPARE(m.surfaces[0].triangles.size(), std::size_t(20 * 16));
        for (const Surface &s : m.surfaces)
            for (const Triangle &t : s.triangles) {
                const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
                const Vec3 normal = (b - a).cross(c - a);
                QVERIFY(normal.dot((a + b + c) / 3.0 - p.centre) > 0.0);
            }
        QVERIFY(std::abs((m.surfaces[1].vertices[7] - p.centre).norm() - 5.0) < 1e-12);
        // Three spheres (thesis Fig 5.9): two shells, each bounded by its two spheres.
        p.middleRadius = 3.5;
        const Model three = nestedSpheres(p);
        QCOMPARE(three.surfaces.size(), std::size_t(3));
        QCOMPARE(three.regions.size(), std::size_t(3));
        QVERIFY(std::abs((three.surfaces[2].vertices[7] - p.centre).norm() - 3.5) < 1e-12);
        QCOMPARE(three.regions[2].boundaries.size(), std::size_t(2));
    }
};

QTEST_GUILESS_MAIN(TestSyntheticModels)
#include "test_synthetic_models.moc"
