// TetGen in its helper process: tets carry their regions and fill them exactly, options reach the
// switches, and every failure (invalid model, crash, kill, time and memory limits, cancel, no
// helper) is a typed outcome of the calling process, which survives them all.
#include "common/error.h"
#include "model/region_volume.h"
#include "tetgen_test_models.h"
#include "volume/plc.h"
#include "volume/tetgen_comparison.h"
#include "volume/tetgen_runner.h"

#include <QtTest>

#include <csignal>
#include <thread>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

std::vector<double> tetVolumes(const VolumeMesh &mesh)
{
    std::vector<double> v(mesh.regionNames.size(), 0.0);
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
        if (mesh.cellRegion[c] >= 0)
            v[mesh.cellRegion[c]] += signedVolume(mesh, mesh.cells[c]);
    return v;
}

// A refinement of the box far too big to finish in a test (about 10^8 tets). With Y TetGen 1.5
// rejects the Steiner points that encroach on the coarse surfaces, so it must refine those too.
TetgenParams hugeRefinement()
{
    TetgenParams p;
    p.maxVolume = 2.0;
    p.refineSurfaces = true;
    return p;
}

// Joins a helper thread on every way out of a test function (QVERIFY returns early).
struct Joiner {
    std::thread thread;
    ~Joiner()
    {
        if (thread.joinable())
            thread.join();
    }
};

bool processGone(int pid)
{
    return ::kill(pid, 0) != 0 && errno == ESRCH;
}

} // namespace

class TestTetgenRunner : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY2(!findTetgenHelper().empty(), "stratamesh-tetgen is built"); }

    void switchesFollowTheOptions()
    {
        TetgenParams p;
        QCOMPARE(tetgenSwitches(p), std::string("pq1.414AY"));
        p.refineSurfaces = true;
        p.quality = 1.2;
        p.maxVolume = 1000;
        QCOMPARE(tetgenSwitches(p), std::string("pq1.2a1000A"));
        p.quality = 0;
        QCOMPARE(tetgenSwitches(p), std::string("pa1000A"));
        p.noMerge = true;
        QCOMPARE(tetgenSwitches(p), std::string("pa1000AM"));
    }

    void tetsFillTheirRegions()
    {
        const Model m = twoRegionBox();
        const TetgenResult r = runTetgen(m, {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "ok");
        QVERIFY(r.message.empty());
        QCOMPARE(r.switches, std::string("pq1.414AY"));
        validateMesh(r.mesh);
        QVERIFY(r.mesh.cells.size() > 100);
        QCOMPARE(r.tetsWithoutRegion, std::size_t(0));
        const std::vector<double> brep = regionVolumes(m);
        const std::vector<double> tets = tetVolumes(r.mesh);
        QCOMPARE(tets.size(), std::size_t(2));
        for (int k = 0; k < 2; ++k) {
            QVERIFY2(std::abs(tets[k] - brep[k]) <= 1e-6 * brep[k],
                     qPrintable(QString::number(tets[k] - brep[k])));
            QVERIFY(std::count(r.mesh.cellRegion.begin(), r.mesh.cellRegion.end(), k) > 0);
        }
        for (const Cell &c : r.mesh.cells)
            QVERIFY(signedVolume(r.mesh, c) > 0);
        // With Y the surfaces keep their triangles: as many boundary faces as input triangles.
        QCOMPARE(r.mesh.triangles.size(), m.triangleCount());
        QVERIFY(std::count(r.mesh.triangleSurface.begin(), r.mesh.triangleSurface.end(), -1) == 0);
    }

    // A hole point in layer2 leaves it empty: layer1 alone is meshed, to its volume.
    void holeLeavesItsZoneEmpty()
    {
        const Model m = twoRegionBox();
        const Vec3 inLayer2 = regionSeed(m, 1).seed;
        const TetgenResult r = runTetgen(m, {inLayer2}, {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "ok");
        QVERIFY(r.mesh.cells.size() > 50);
        QCOMPARE(std::count(r.mesh.cellRegion.begin(), r.mesh.cellRegion.end(), 1), 0L);
        QCOMPARE(r.tetsWithoutRegion, std::size_t(0));
        const std::vector<double> brep = regionVolumes(m);
        const std::vector<double> tets = tetVolumes(r.mesh);
        QVERIFY(std::abs(tets[0] - brep[0]) <= 1e-6 * brep[0]);
    }

    // A region in two pieces gets one seed; TetGen numbers the other piece itself.
    void regionInTwoPiecesIsFilled()
    {
        LayeredBoxParams p;
        p.horizons = 2;
        p.edgeLength = 150.0;
        Model m = recoverTopology(layeredBox(p));
        QCOMPARE(m.regions.size(), std::size_t(3));
        m.regions[0].boundaries.insert(m.regions[0].boundaries.end(),
                                       m.regions[2].boundaries.begin(),
                                       m.regions[2].boundaries.end());
        m.regions.pop_back();
        m.layers.clear();
        const std::vector<double> brep = regionVolumes(m);
        const TetgenResult r = runTetgen(m, {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "ok");
        QVERIFY(r.tetsLocatedByCentroid > 0);
        QCOMPARE(r.tetsWithoutRegion, std::size_t(0));
        const std::vector<double> tets = tetVolumes(r.mesh);
        for (int k = 0; k < 2; ++k)
            QVERIFY2(std::abs(tets[k] - brep[k]) <= 1e-6 * brep[k],
                     qPrintable(QString::number(tets[k] - brep[k])));
    }

    void optionsRefine()
    {
        const Model m = twoRegionBox();
        const std::size_t base = runTetgen(m, {}).mesh.cells.size();
        TetgenParams fine;
        fine.maxVolume = 2.4e8 / 20000;
        fine.refineSurfaces = true;
        const TetgenResult refined = runTetgen(m, fine);
        QCOMPARE(tetgenOutcomeName(refined.outcome), "ok");
        QVERIFY(refined.mesh.cells.size() > 10000);
        QVERIFY(refined.mesh.cells.size() > 2 * base);
        QVERIFY(refined.mesh.triangles.size() > m.triangleCount());
        const std::vector<double> brep = regionVolumes(m);
        const std::vector<double> tets = tetVolumes(refined.mesh);
        for (int k = 0; k < 2; ++k)
            QVERIFY(std::abs(tets[k] - brep[k]) <= 1e-6 * brep[k]);
    }

    void selfIntersectionIsInvalidInput()
    {
        const Model m = selfIntersectingBox();
        const TetgenResult r = runTetgen(m, {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "invalid_input");
        QVERIFY(r.seconds == 0.0); // TetGen never ran
        const std::string horizon = m.surfaces[horizonOf(m)].name;
        QVERIFY(std::find(r.surfaces.begin(), r.surfaces.end(), "piercer") != r.surfaces.end());
        QVERIFY(std::find(r.surfaces.begin(), r.surfaces.end(), horizon) != r.surfaces.end());
        QVERIFY2(r.message.find("piercer") != std::string::npos, r.message.c_str());
        QVERIFY2(r.message.find("intersecting") != std::string::npos, r.message.c_str());
    }

    void duplicatedTriangleIsInvalidInput()
    {
        const Model m = duplicatedTriangleBox();
        const TetgenResult r = runTetgen(m, {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "invalid_input");
        const std::string horizon = m.surfaces[horizonOf(m)].name;
        QVERIFY(std::find(r.surfaces.begin(), r.surfaces.end(), "copy") != r.surfaces.end());
        QVERIFY(std::find(r.surfaces.begin(), r.surfaces.end(), horizon) != r.surfaces.end());
        QVERIFY2(r.message.find("two surfaces") != std::string::npos, r.message.c_str());
    }

    // Unchecked, the self-intersecting model makes TetGen fail: a result, never a crash here.
    void tetgenFailureIsAborted()
    {
        TetgenParams p;
        p.checkInput = false;
        const TetgenResult r = runTetgen(selfIntersectingBox(), p);
        QCOMPARE(tetgenOutcomeName(r.outcome), "aborted");
        QVERIFY(!r.message.empty());
        QVERIFY(!r.lastOutput.empty());
        qInfo("%s", r.message.c_str());
    }

    void killedHelperIsKilled()
    {
        TetgenParams p = hugeRefinement();
        int helper = 0;
        Joiner killer;
        p.onStarted = [&](int pid) {
            helper = pid;
            killer.thread = std::thread([pid] {
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
                ::kill(pid, SIGKILL);
            });
        };
        const TetgenResult r = runTetgen(twoRegionBox(), p);
        QCOMPARE(tetgenOutcomeName(r.outcome), "killed");
        QCOMPARE(r.signal, SIGKILL);
        QVERIFY2(r.message.find("killed") != std::string::npos, r.message.c_str());
        QVERIFY(processGone(helper));
    }

    void timeLimitGivesTimedOut()
    {
        TetgenParams p = hugeRefinement();
        p.timeLimitSeconds = 1.0;
        int helper = 0;
        p.onStarted = [&](int pid) { helper = pid; };
        const TetgenResult r = runTetgen(twoRegionBox(), p);
        QCOMPARE(tetgenOutcomeName(r.outcome), "timed_out");
        QVERIFY(r.seconds >= 1.0 && r.seconds < 5.0);
        QVERIFY(processGone(helper));
    }

    void memoryLimitGivesOutOfMemory()
    {
        TetgenParams p = hugeRefinement();
        p.memoryLimitMB = 200;
        p.timeLimitSeconds = 50;
        const TetgenResult r = runTetgen(twoRegionBox(), p);
        QVERIFY2(r.outcome == TetgenOutcome::OutOfMemory,
                 (std::string(tetgenOutcomeName(r.outcome)) + ": " + r.message).c_str());
        qInfo("%s", r.message.c_str());
    }

    void cancelKillsTheHelper()
    {
        TetgenParams p = hugeRefinement();
        Progress progress;
        int helper = 0;
        Joiner canceller;
        p.onStarted = [&](int pid) {
            helper = pid;
            canceller.thread = std::thread([&progress] {
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
                progress.cancel();
            });
        };
        QVERIFY_THROWS_EXCEPTION(Cancelled, runTetgen(twoRegionBox(), p, progress));
        QVERIFY(helper > 0);
        QVERIFY(processGone(helper));
    }

    void comparisonRunsBothSides()
    {
        Progress progress;
        double last = 0.0;
        bool monotonic = true;
        Progress tracked([&](double f, const std::string &) {
            monotonic = monotonic && f >= last - 1e-12;
            last = f;
        });
        const TetmeshComparison c =
            compareTetmeshes(twoRegionBox(150), twoRegionBox(75), {}, tracked);
        QCOMPARE(tetgenOutcomeName(c.input.result.outcome), "ok");
        QCOMPARE(tetgenOutcomeName(c.output.result.outcome), "ok");
        QVERIFY(c.output.quality.tets > c.input.quality.tets);
        QVERIFY(monotonic);
        QCOMPARE(last, 1.0);
        for (const TetmeshSide *side : {&c.input, &c.output}) {
            QCOMPARE(side->regions.size(), std::size_t(2));
            QCOMPARE(side->result.mesh.cellQuality.size(), side->result.mesh.cells.size());
            for (int k = 0; k < 2; ++k)
                QVERIFY(std::abs(side->regions[k].volume - side->brepVolumes[k])
                        <= 1e-6 * side->brepVolumes[k]);
        }
        // A failed side is that side's result; the other still runs.
        const TetmeshComparison bad = compareTetmeshes(selfIntersectingBox(), twoRegionBox(), {});
        QCOMPARE(tetgenOutcomeName(bad.input.result.outcome), "invalid_input");
        QCOMPARE(bad.input.quality.tets, std::size_t(0));
        QCOMPARE(tetgenOutcomeName(bad.output.result.outcome), "ok");
        // A cancel stops it.
        Progress cancelled;
        cancelled.cancel();
        QVERIFY_THROWS_EXCEPTION(Cancelled,
                                 compareTetmeshes(twoRegionBox(), twoRegionBox(), {}, cancelled));
    }

    void badModelsAreResults()
    {
        Model nan = twoRegionBox();
        nan.surfaces[0].vertices[0].x() = std::nan("");
        nan.vertices.clear();
        nan.surfaceVertexToGlobal.clear();
        QCOMPARE(tetgenOutcomeName(runTetgen(nan, {}).outcome), "invalid_input");
        Model open = twoRegionBox();
        open.regions[0].boundaries.resize(1);
        TetgenParams unchecked;
        unchecked.checkInput = false;
        const TetgenResult r = runTetgen(open, unchecked);
        QCOMPARE(tetgenOutcomeName(r.outcome), "invalid_input");
        QVERIFY2(r.message.find(open.regions[0].name) != std::string::npos, r.message.c_str());
        TetgenParams negative;
        negative.quality = -1;
        QVERIFY_THROWS_EXCEPTION(InputError, runTetgen(twoRegionBox(), negative));
        qputenv("TMPDIR", "/nonexistent-folder");
        const TetgenResult noTmp = runTetgen(twoRegionBox(), {});
        qunsetenv("TMPDIR");
        QCOMPARE(tetgenOutcomeName(noTmp.outcome), "aborted");
        QVERIFY2(noTmp.message.find("work folder") != std::string::npos, noTmp.message.c_str());
    }

    void missingHelperIsAborted()
    {
        TetgenParams p;
        p.helperPath = "/nonexistent/stratamesh-tetgen";
        const TetgenResult r = runTetgen(twoRegionBox(), p);
        QCOMPARE(tetgenOutcomeName(r.outcome), "aborted");
        QVERIFY2(r.message.find("not found") != std::string::npos, r.message.c_str());
    }
};

QTEST_GUILESS_MAIN(TestTetgenRunner)
#include "test_tetgen_runner.moc"
