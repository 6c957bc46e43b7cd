// Local counts per Voronoi cell (thesis §3.3.2) on models built in code.
#include "complexity/box_elements.h"
#include "complexity/cell_element_counts.h"
#include "complexity/local_complexity.h"
#include "model/synthetic_models.h"
#include "model/topology.h"

#include <QtTest>

#include <tbb/global_control.h>

#include <cmath>

using namespace stratamesh;

namespace {

Model layered(int horizons, double fold = 0.0, bool fault = false)
{
    LayeredBoxParams p;
    p.horizons = horizons;
    p.foldAmplitude = fold;
    p.fault = fault;
    p.faultDipDegrees = 90.0;
    p.edgeLength = 50.0;
    return recoverTopology(layeredBox(p));
}

// The box clipped to the slab zLo <= z <= zHi, as a single hand-made cell.
ConvexPolyhedron slab(const Model &model, double zLo, double zHi)
{
    ConvexPolyhedron cell = ConvexPolyhedron::box(modelBounds(model));
    cell.clip({Vec3(0, 0, 1), zHi, -10});
    cell.clip({Vec3(0, 0, -1), -zLo, -11});
    return cell;
}

} // namespace

class TestCellElementCounts : public QObject {
    Q_OBJECT
private slots:
    void singleRegionCountsOne()
    {
        const Model model = layered(0);
        QCOMPARE(model.regions.size(), std::size_t(1));
        LocalComplexityParams params;
        params.cells = 300;
        params.iterations = 5;
        const LocalComplexity local = localComplexity(model, params);
        QCOMPARE(local.counts.size(), std::size_t(300));
        for (const CellElementCounts &c : local.counts) {
            QCOMPARE(c.regions, 1);
            QCOMPARE(c.surfaces + c.lines + c.corners, 0);
        }
        QCOMPARE(local.statistics.max, 1);
        QCOMPARE(local.statistics.q10, 1);
        QCOMPARE(local.outsideCells, 0);
    }

    void flatHorizonCellsCountThreeWhenCut()
    {
        const Model model = layered(1);
        // Where is the horizon? The only inner surface is flat.
        const BoxElements box = boxElements(model);
        QCOMPARE(box.innerSurfaces().size(), std::size_t(1));
        const Surface &horizon = model.surfaces[box.innerSurfaces().front()];
        const double z = horizon.vertices.front().z();
        LocalComplexityParams params;
        params.cells = 400;
        params.iterations = 5;
        params.seed = 9;
        const LocalComplexity local = localComplexity(model, params);
        int cut = 0;
        for (std::size_t i = 0; i < local.counts.size(); ++i) {
            const Box3 b = local.cvt.cells[i].bounds();
            const bool crosses = b.min().z() < z - 1e-6 && b.max().z() > z + 1e-6;
            const bool away = b.min().z() > z + 1e-6 || b.max().z() < z - 1e-6;
            if (!crosses && !away)
                continue; // touches the horizon plane: either is right
            cut += crosses;
            QCOMPARE(local.counts[i].total(), crosses ? 3 : 1);
            QCOMPARE(local.counts[i].surfaces, crosses ? 1 : 0);
            QCOMPARE(local.counts[i].regions, crosses ? 2 : 1);
        }
        QVERIFY(cut > 10);
        QCOMPARE(local.statistics.max, 3);
    }

    void foldedHorizonGivesTwoPiecesInASlab()
    {
        // z = c + A sin(π y / Ly): a thin slab below the crest cuts both flanks apart.
        const double amplitude = 100.0;
        const Model model = layered(1, amplitude, true);
        const BoxElements box = boxElements(model);
        double crest = -1e300;
        for (int s : box.innerSurfaces())
            if (model.surfaces[s].type == FeatureType::Horizon)
                for (const Vec3 &p : model.surfaces[s].vertices)
                    crest = std::max(crest, p.z());
        const double z = crest - 0.5 * amplitude;
        const ConvexPolyhedron cell = slab(model, z - 5.0, z + 5.0);
        const Vec3 site = cell.centroid();
        const auto counts = countElementsInCells(model, {site}, {cell});
        // The vertical fault (throw 0) splits the horizon into two surfaces and is split by it
        // into a part below and a part above their contact line z = c + A sin(π y / Ly).
        QCOMPARE(box.innerSurfaces().size(), std::size_t(4));
        QCOMPARE(box.innerLines().size(), std::size_t(1));
        QCOMPARE(model.regions.size(), std::size_t(4));
        // In the slab: each horizon half on both flanks (4 pieces); the fault below the contact
        // in the middle (1) and above it at both ends (2); the contact line crosses it twice.
        QCOMPARE(counts[0].surfaces, 7);
        QCOMPARE(counts[0].lines, 2);
        QCOMPARE(counts[0].regions, 4);
        QCOMPARE(counts[0].corners, 0);
        // A slab above the crest meets one region per fault block only.
        const ConvexPolyhedron top = slab(model, crest + 10.0, crest + 20.0);
        const auto above = countElementsInCells(model, {top.centroid()}, {top});
        QCOMPARE(above[0].surfaces, 1);
        QCOMPARE(above[0].regions, 2);
        QCOMPARE(above[0].lines, 0);
    }

    void cellsOutsideTheModelAreLeftOut()
    {
        // A spherical model in its bounding box: the box corners are outside every region.
        NestedSpheresParams p;
        p.innerRadius = 1.0;
        p.outerRadius = 2.0;
        const Model model = recoverTopology(nestedSpheres(p));
        LocalComplexityParams params;
        params.cells = 400;
        params.iterations = 5;
        const LocalComplexity local = localComplexity(model, params);
        int outside = 0;
        int crossing = 0;
        for (std::size_t i = 0; i < local.counts.size(); ++i) {
            const CellElementCounts &c = local.counts[i];
            QCOMPARE(c.lines + c.corners, 0);
            const double r = local.cvt.sites[i].norm();
            if (c.total() == 0) {
                ++outside;
                QVERIFY(r > 2.0 - 1e-9); // a site outside the outer sphere
            }
            if (c.surfaces == 1) {
                ++crossing;
                QCOMPARE(c.regions, 2); // the inner sphere separates "inner" and "shell"
            }
        }
        QVERIFY(outside > 0);
        QVERIFY(crossing > 0);
        QCOMPARE(local.outsideCells, outside);
        QCOMPARE(local.statistics.cells, 400 - outside);
        QCOMPARE(local.statistics.q10, 1);
    }

    void sameSeedSameCounts()
    {
        const Model model = layered(2, 80.0, true);
        LocalComplexityParams params;
        params.cells = 500;
        params.iterations = 8;
        params.seed = 7;
        const LocalComplexity a = localComplexity(model, params);
        const LocalComplexity b = localComplexity(model, params);
        QCOMPARE(a.statistics.q90, b.statistics.q90);
        QCOMPARE(a.statistics.mean, b.statistics.mean);
        QCOMPARE(a.statistics.varCoeff, b.statistics.varCoeff);
        for (std::size_t i = 0; i < a.counts.size(); ++i)
            QCOMPARE(a.counts[i].total(), b.counts[i].total());
        QVERIFY(a.statistics.max > 3);
        // One thread gives the same sites and counts as many.
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        const LocalComplexity c = localComplexity(model, params);
        QVERIFY(c.cvt.sites == a.cvt.sites);
        for (std::size_t i = 0; i < a.counts.size(); ++i)
            QCOMPARE(c.counts[i].total(), a.counts[i].total());
    }
};

QTEST_GUILESS_MAIN(TestCellElementCounts)
#include "test_cell_element_counts.moc"
