// Geometric complexity C_t + C_f + C_e + C_a (thesis §3.3.1, Table 3.2) on models built in code.
#include "common/error.h"
#include "complexity/angle_measure.h"
#include "complexity/box_elements.h"
#include "complexity/geometric_complexity.h"
#include "complexity/region_thickness.h"
#include "complexity/shape_measure.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

namespace {

const ElementMeasures &measuresOf(const std::vector<ElementMeasures> &all, int element)
{
    for (const ElementMeasures &m : all)
        if (m.element == element)
            return m;
    throw std::runtime_error("element not measured");
}

std::vector<int> innerSurfacesOfType(const Model &model, FeatureType type)
{
    std::vector<int> out;
    for (int s : boxElements(model).innerSurfaces())
        if (model.surfaces[s].type == type)
            out.push_back(s);
    return out;
}

} // namespace

class TestGeometricComplexity : public QObject {
    Q_OBJECT
private slots:
    void flatHorizonIsSimple()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        const Model model = recoverTopology(layeredBox(p));
        const GeometricComplexity g = geometricComplexity(model, GeometricParams{});
        QCOMPARE(g.surfaces.size(), std::size_t(1));
        const ElementMeasures &h = g.surfaces.front();
        QVERIFY(std::abs(h.shape) < 1e-12); // C_f
        QCOMPARE(h.angle, 0.0);             // C_a: four right-angled corners
        QCOMPARE(h.size, 0.0);
        QCOMPARE(h.thickness, 0.0);
        QCOMPARE(g.lines.size(), std::size_t(0));
        for (const ElementMeasures &r : g.regions) {
            QCOMPARE(r.angle, 0.0);
            QCOMPARE(r.size, 0.0);
            // A 1000 × 600 × 200 layer is within h = 100 of another of its sides on a 100 m strip
            // along the edges of its top and bottom (2 × 280 000 m²) and all over its 200 m high
            // sides (640 000 m²), out of 1 840 000 m².
            QVERIFY2(std::abs(r.thickness - 1200000.0 / 1840000.0) < 0.01,
                     qPrintable(QString::number(r.thickness)));
        }
        // The same regions are below h³ when h is large.
        GeometricParams big;
        big.h = 1000.0;
        const GeometricComplexity g2 = geometricComplexity(model, big);
        for (const ElementMeasures &r : g2.regions)
            QCOMPARE(r.size, 1.0);
    }

    void thinLayerIsThinOnBothHorizons()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        p.thinLayerThickness = 30.0;
        const Model model = recoverTopology(layeredBox(p));
        const std::vector<double> volumes = regionVolumes(model);
        const int thin =
            static_cast<int>(std::min_element(volumes.begin(), volumes.end()) - volumes.begin());
        const auto areas = regionSideThinAreas(model, 100.0);
        int horizonSides = 0;
        for (const SideThinArea &a : areas[thin]) {
            if (model.surfaces[a.side.surface].type != FeatureType::Horizon)
                continue;
            ++horizonSides;
            QVERIFY(a.all > 0.0);
            QVERIFY(std::abs(a.thin - a.all) < 1e-6 * a.all); // 30 m < h everywhere
        }
        QCOMPARE(horizonSides, 2);
        const GeometricComplexity g = geometricComplexity(model, GeometricParams{});
        const double ce = measuresOf(g.regions, thin).thickness;
        QVERIFY(std::abs(ce - 1.0) < 1e-12); // thin everywhere
        for (const ElementMeasures &r : g.regions)
            if (r.element != thin)
                QVERIFY(r.thickness < 0.7);
        // Below the layer's thickness, its horizons are thin only near the box sides.
        GeometricParams small;
        small.h = 20.0;
        const auto smallAreas = regionSideThinAreas(model, small.h);
        for (const SideThinArea &a : smallAreas[thin])
            if (model.surfaces[a.side.surface].type == FeatureType::Horizon)
                QVERIFY(a.thin < 0.1 * a.all);
        QVERIFY(measuresOf(geometricComplexity(model, small).regions, thin).thickness < 0.2);
    }

    void lowAngleContactIsSharp()
    {
        // A fault dipping 10° cuts flat horizons at 10°: the wedges between them are sharp.
        LayeredBoxParams p;
        p.size = Vec3(5000.0, 600.0, 400.0);
        p.horizons = 1;
        p.fault = true;
        p.faultDipDegrees = 10.0;
        p.faultThrow = 20.0;
        p.edgeLength = 100.0;
        const Model model = recoverTopology(layeredBox(p));
        GeometricParams params;
        const GeometricComplexity g = geometricComplexity(model, params);
        double sharp = 0.0;
        for (const ElementMeasures &r : g.regions)
            sharp += r.angle;
        QVERIFY(sharp > 0.0);
        params.alphaDegrees = 5.0;
        const GeometricComplexity g2 = geometricComplexity(model, params);
        for (const ElementMeasures &r : g2.regions)
            QCOMPARE(r.angle, 0.0);
        // A 60° fault stays blunt at α = 20°.
        p.size = Vec3(1000.0, 600.0, 400.0);
        p.faultDipDegrees = 60.0;
        const GeometricComplexity g3 =
            geometricComplexity(recoverTopology(layeredBox(p)), GeometricParams{});
        for (const ElementMeasures &r : g3.regions)
            QCOMPARE(r.angle, 0.0);
    }

    void wedgeAngles()
    {
        const double ten = 10.0 * M_PI / 180.0;
        const Vec3 v0(1, 0, 0);
        const Vec3 v1(std::cos(ten), std::sin(ten), 0);
        QVERIFY(std::abs(wedgeAngle(v0, Vec3(0, 1, 0), {v1}) - ten) < 1e-12);
        QVERIFY(std::abs(wedgeAngle(v0, Vec3(0, -1, 0), {v1}) - (2 * M_PI - ten)) < 1e-12);
        QCOMPARE(wedgeAngle(v0, Vec3(0, 1, 0), {}), 2 * M_PI);
        QCOMPARE(wedgeAngle(v0, Vec3(0, 1, 0), {v0}), 2 * M_PI);
    }

    void foldedHorizonShape()
    {
        // z = c + A sin(π y / L): projected onto its mean (horizontal) plane the horizon covers
        // Lx·L; its area is Lx times the arc length of the sine.
        LayeredBoxParams p;
        p.horizons = 1;
        p.foldAmplitude = 120.0;
        p.edgeLength = 20.0;
        const Model model = recoverTopology(layeredBox(p));
        const std::vector<int> horizons = innerSurfacesOfType(model, FeatureType::Horizon);
        QCOMPARE(horizons.size(), std::size_t(1));
        const double L = p.size.y();
        double arc = 0.0;
        const int n = 100000;
        for (int i = 0; i < n; ++i) {
            const double y = (i + 0.5) * L / n;
            const double slope = p.foldAmplitude * M_PI / L * std::cos(M_PI * y / L);
            arc += std::sqrt(1 + slope * slope) * L / n;
        }
        const double expected = 1.0 - L / arc;
        const double cf = surfaceShapeMeasure(model.surfaces[horizons.front()]);
        QVERIFY2(std::abs(cf - expected) < 0.02 * expected,
                 qPrintable(QString("C_f %1, expected %2").arg(cf).arg(expected)));
        // The line where the folded horizon meets a vertical fault has the same shape measure.
        p.fault = true;
        p.faultDipDegrees = 90.0;
        const Model faulted = recoverTopology(layeredBox(p));
        const BoxElements box = boxElements(faulted);
        QCOMPARE(box.innerLines().size(), std::size_t(1));
        const double lf = lineShapeMeasure(faulted, faulted.lines[box.innerLines().front()]);
        QVERIFY2(std::abs(lf - expected) < 0.02 * expected,
                 qPrintable(QString("line C_f %1, expected %2").arg(lf).arg(expected)));
    }

    void narrowFaultStripIsThin()
    {
        // The fault strip between the two horizons of a 30 m layer is narrower than h = 100 m.
        LayeredBoxParams p;
        p.horizons = 1;
        p.thinLayerThickness = 30.0;
        p.fault = true;
        p.faultDipDegrees = 90.0;
        p.edgeLength = 25.0;
        const Model model = recoverTopology(layeredBox(p));
        const GeometricComplexity g = geometricComplexity(model, GeometricParams{});
        double widest = 0.0;
        for (const ElementMeasures &m : g.surfaces)
            if (model.surfaces[m.element].type == FeatureType::Fault)
                widest = std::max(widest, m.thickness);
        QVERIFY(widest > 0.5);
        GeometricParams small;
        small.h = 10.0;
        for (const ElementMeasures &m : geometricComplexity(model, small).surfaces)
            QCOMPARE(m.thickness, 0.0);
    }

    void badParameters()
    {
        LayeredBoxParams p;
        p.horizons = 1;
        const Model model = recoverTopology(layeredBox(p));
        GeometricParams bad;
        bad.h = 0.0;
        QVERIFY_THROWS_EXCEPTION(InputError, geometricComplexity(model, bad));
        bad.h = 100.0;
        bad.alphaDegrees = -3.0;
        QVERIFY_THROWS_EXCEPTION(InputError, geometricComplexity(model, bad));
        QVERIFY_THROWS_EXCEPTION(InputError, geometricComplexity(layeredBox(p), GeometricParams{}));
    }
};

QTEST_GUILESS_MAIN(TestGeometricComplexity)
#include "test_geometric_complexity.moc"
