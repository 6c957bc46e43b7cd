// Thin strips found and removed whole before remeshing (thin_strips.h, strip_collapse.h).
#include "common/error.h"
#include "io/model_reader.h"
#include "model/model_counts.h"
#include "model/region_volume.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"
#include "remesh/strip_collapse.h"
#include "remesh/surface_remesher.h"
#include "support/model_lines.h"
#include "support/test_data.h"

#include <QtTest>

#include <cmath>
#include <numeric>

using namespace stratamesh;

namespace {

Model faultedBox(double faultThrow)
{
    LayeredBoxParams bp;
    bp.size = Vec3(1000, 600, 400);
    bp.horizons = 1;
    bp.fault = true;
    bp.faultThrow = faultThrow;
    bp.edgeLength = 40;
    return recoverTopology(layeredBox(bp));
}

// Lines where the horizon's two fault blocks meet the fault together (the throw is cancelled).
int joinedLines(const Model &m)
{
    return test::countLines(m,
                            [](int horizons, int faults) { return horizons >= 2 && faults >= 1; });
}

} // namespace

class TestThinStrips : public QObject {
    Q_OBJECT
private slots:
    void stripOfSmallThrowFoundBelowItsWidthOnly()
    {
        const Model input = faultedBox(15);
        const std::vector<ThinStrip> strips = findThinStrips(input, 40);
        QCOMPARE(strips.size(), std::size_t(1));
        const ThinStrip &s = strips.front();
        QCOMPARE(input.surfaces[s.surface].type, FeatureType::Fault);
        QVERIFY2(s.width >= 15 - 1e-6 && s.width < 40, qPrintable(QString::number(s.width)));
        QVERIFY(s.length > 500);
        for (int l : s.lines)
            QVERIFY(std::find(input.surfaces[s.surface].lines.begin(),
                              input.surfaces[s.surface].lines.end(), l)
                    != input.surfaces[s.surface].lines.end());
        QVERIFY(findThinStrips(input, 10).empty());
        QVERIFY(findThinStrips(faultedBox(80), 40).empty());
    }

    void removedStripLeavesValidModelWithSameVolumes()
    {
        const Model input = faultedBox(15);
        QVERIFY(checkValidity(input).valid);
        QCOMPARE(joinedLines(input), 0);
        SimplificationLedger ledger;
        const StripCollapse collapsed = removeThinStrips(input, 40, ledger);
        QCOMPARE(collapsed.removed.size(), std::size_t(1));
        const Model &out = collapsed.model;
        QCOMPARE(out.surfaces.size(), input.surfaces.size() - 1);
        QCOMPARE(out.regions.size(), input.regions.size());
        const ValidityReport validity = checkValidity(out);
        QVERIFY2(validity.valid,
                 validity.problems.empty() ? "" : validity.problems.front().message.c_str());
        QVERIFY(joinedLines(out) >= 1);
        // The strip had no volume of its own: the regions still fill the box.
        const std::vector<double> volumes = regionVolumes(out);
        for (double v : volumes)
            QVERIFY(v > 0);
        const double total = std::accumulate(volumes.begin(), volumes.end(), 0.0);
        QVERIFY2(std::abs(total - boxEnclosedVolume(out)) <= 1e-9 * total,
                 qPrintable(QString::number(total)));
        // Names kept, the strip's gone, and the ledger says so.
        const std::string gone = input.surfaces[collapsed.removed.front().surface].name;
        for (std::size_t s = 0; s < out.surfaces.size(); ++s) {
            QVERIFY(out.surfaces[s].name != gone);
            QCOMPARE(out.surfaces[s].name, input.surfaces[collapsed.surfaceToInput[s]].name);
        }
        QCOMPARE(countKind(ledger, LedgerKind::SurfaceLost), 1);
        QCOMPARE(ledger.size(), std::size_t(2));
        for (const LedgerRecord &r : ledger)
            QCOMPARE(r.inputs.front().name, gone);
        // The merge names the strip's two long lines, as the input numbers them.
        const LedgerRecord &merge =
            ledger.front().kind == LedgerKind::CloseFeatureMerge ? ledger.front() : ledger.back();
        QCOMPARE(merge.inputs.size(), std::size_t(3));
        const std::vector<int> &stripLines =
            input.surfaces[collapsed.removed.front().surface].lines;
        for (std::size_t k = 1; k < 3; ++k) {
            QCOMPARE(merge.inputs[k].kind, EntityKind::Line);
            QVERIFY(std::find(stripLines.begin(), stripLines.end(), merge.inputs[k].id)
                    != stripLines.end());
        }
    }

    void cancelStopsBetweenStrips()
    {
        const Model input = faultedBox(15);
        SimplificationLedger ledger;
        Progress progress;
        int ticks = 0;
        Progress counting(
            [&](double, const std::string &stage) { ticks += stage == "thin strips" ? 1 : 0; });
        removeThinStrips(input, 40, ledger, counting);
        QVERIFY(ticks >= 2); // one per strip tried, one to find none left
        progress.cancel();
        ledger.clear();
        QVERIFY_THROWS_EXCEPTION(Cancelled, removeThinStrips(input, 40, ledger, progress));
        QVERIFY(ledger.empty());
    }

    void remeshWithStripFactorCancelsTheThrow()
    {
        const Model input = faultedBox(15);
        RemeshParams params;
        params.edgeLength = 90;
        params.iterations = 40;
        params.stripWidthFactor = 0.3; // 27 m: the 15 m strip goes
        const RemeshResult result = remeshModel(input, params);
        QCOMPARE(result.strips.size(), std::size_t(1));
        const ValidityReport validity = checkValidity(result.model);
        QVERIFY2(validity.valid,
                 validity.problems.empty() ? "" : validity.problems.front().message.c_str());
        QVERIFY(joinedLines(result.model) >= 1);
        QCOMPARE(countEntities(result.model).all.surfaces, countEntities(input).all.surfaces - 1);
        params.stripWidthFactor = 0.1; // 9 m: kept
        QVERIFY(remeshModel(input, params).strips.empty());
    }

    // An explicit d_resolution also bounds the strips removed: 0 asks for no simplification,
    // so the strip stays whatever the strip factor; the default removes it by the factor alone.
    void dResolutionBoundsTheStripsRemoved()
    {
        const Model input = faultedBox(15);
        RemeshParams params;
        params.edgeLength = 90;
        params.iterations = 40;
        params.stripWidthFactor = 0.3; // 27 m
        QCOMPARE(params.dResolution, kAutoDResolution);
        QCOMPARE(stripWidthLimit(params, 90.0), 27.0);
        QVERIFY(!pinsFeatures(params));
        params.dResolution = 0.0;
        QCOMPARE(stripWidthLimit(params, 90.0), 0.0);
        QVERIFY(pinsFeatures(params)); // keeping everything pins sites on the close features
        const RemeshResult kept = remeshModel(input, params);
        QVERIFY(kept.strips.empty());
        QCOMPARE(countKind(kept.ledger, LedgerKind::SurfaceLost), 0);
        QCOMPARE(countEntities(kept.model).all.surfaces, countEntities(input).all.surfaces);
        qInfo("d_resolution 0: %d sites", kept.siteCount);
        QCOMPARE(countTopologyEdits(kept.ledger).total(), 0);
        params.dResolution = 10.0; // below the 15 m strip: kept
        QCOMPARE(stripWidthLimit(params, 90.0), 10.0);
        QVERIFY(!pinsFeatures(params));
        QVERIFY(remeshModel(input, params).strips.empty());
        params.dResolution = 20.0; // above it: removed, though no close parts are left to merge
        QCOMPARE(remeshModel(input, params).strips.size(), std::size_t(1));
        QCOMPARE(mergeDistance(params), 20.0);
        params.dResolution = kAutoDResolution;
        QCOMPARE(mergeDistance(params), 0.0);
    }

    // modelA5's fault piece f3_1 runs 3.8 km between the cutoffs of h1 and h2, at most 18.5 m
    // from both, and f1_3 94 m wide. Both stayed, with every one of f3_1's 62 output triangles
    // under 30° at 5000 sites: half-way folds or crosses a neighbour, and an h1 triangle away
    // from the lines, whose own normal disagrees with its corners', was taken for a fold.
    void stripsWithSliverNeighboursGoOntoOneOfTheirLines()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA5.ml");
        const Model input = recoverTopology(readModel(path.toStdString()));
        // 0.4 × the edge length of 5000 sites, the default strip factor there.
        const double limit = 0.4 * edgeLengthForSites(modelArea(input), 5000);
        std::vector<std::string> found;
        for (const ThinStrip &s : findThinStrips(input, limit))
            found.push_back(input.surfaces[s.surface].name);
        QVERIFY(std::find(found.begin(), found.end(), "f3_1") != found.end());
        SimplificationLedger ledger;
        const StripCollapse collapsed = removeThinStrips(input, limit, ledger);
        std::vector<std::string> removed;
        for (const ThinStrip &s : collapsed.removed)
            removed.push_back(input.surfaces[s.surface].name);
        QVERIFY2(std::find(removed.begin(), removed.end(), "f3_1") != removed.end(), "f3_1 kept");
        QVERIFY2(std::find(removed.begin(), removed.end(), "f1_3") != removed.end(), "f1_3 kept");
        QCOMPARE(countKind(ledger, LedgerKind::SurfaceLost), static_cast<int>(removed.size()));
        // Removal never adds a problem (the input has none).
        QVERIFY(checkValidity(input).valid);
        const ValidityReport validity = checkValidity(collapsed.model);
        QVERIFY2(validity.valid,
                 validity.problems.empty() ? "" : validity.problems.front().message.c_str());
        QCOMPARE(collapsed.model.regions.size(), input.regions.size());
    }
};

QTEST_GUILESS_MAIN(TestThinStrips)
#include "test_thin_strips.moc"
