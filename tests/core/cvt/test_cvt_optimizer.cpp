// Site optimisation: the sphere of thesis Fig 1.9, monotone energies, determinism across
// thread counts, and the boundary term pulling sites onto lines.
#include "core/voronoi/test_shapes.h"
#include "cvt/cvt_energy.h"
#include "cvt/cvt_optimizer.h"
#include "cvt/initial_sampling.h"
#include "quality/restricted_delaunay_quality.h"

#include <QtTest>

#include <Eigen/Geometry>

using namespace stratamesh;

namespace {

// Distance from the sites whose cell meets a line to the nearest line segment: plain mean and
// mean weighted by the length of line in the cell.
struct LineDistance {
    double mean = 0;
    double weighted = 0;
};
LineDistance distanceToLines(const RestrictionDomain &d, const std::vector<Vec3> &sites)
{
    CellIntegralsWorkspace ws;
    const CvtEvaluation e = evaluateCvtEnergy(d, sites, 0.5, ws);
    double sum = 0, weighted = 0, length = 0;
    int n = 0;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        if (!(e.cells.length[i] > 0))
            continue;
        double best = 1e300;
        for (const auto &s : d.segments) {
            const Vec3 a = d.points[s[0]], b = d.points[s[1]];
            const double t =
                std::clamp((sites[i] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
            best = std::min(best, (a + t * (b - a) - sites[i]).norm());
        }
        sum += best;
        weighted += e.cells.length[i] * best;
        length += e.cells.length[i];
        ++n;
    }
    return {sum / std::max(n, 1), weighted / std::max(length, 1e-300)};
}

void verifyDecreasing(const CvtResult &r)
{
    QVERIFY(!r.energy.empty());
    QVERIFY(r.energy.front() < r.initialEnergy);
    for (std::size_t k = 1; k < r.energy.size(); ++k)
        QVERIFY2(
            r.energy[k] <= r.energy[k - 1],
            qPrintable(
                QString("iteration %1: %2 > %3").arg(k + 1).arg(r.energy[k]).arg(r.energy[k - 1])));
}

} // namespace

class TestCvtOptimizer : public QObject {
    Q_OBJECT
private slots:
    void sphereHundredSites()
    {
        // Thesis Fig 1.9: 100 sites near a sphere become an almost equilateral RDT.
        const RestrictionDomain d = test::sphereDomain(4);
        const std::vector<Vec3> initial = sampleSurfaces(d, 100, 42);
        CvtParams params;
        params.iterations = 100;
        int reports = 0;
        params.onIteration = [&](const CvtIterationReport &r) { QCOMPARE(r.iteration, ++reports); };
        const CvtResult r = optimizeCvt(d, initial, params);
        QCOMPARE(reports, r.iterations);
        QCOMPARE(static_cast<int>(r.energy.size()), r.iterations);
        verifyDecreasing(r);
        QVERIFY(r.gradientNorm.back() < 1e-2 * r.initialGradientNorm);

        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(d, r.sites);
        const RestrictedDelaunayQuality q = restrictedDelaunayQuality(restrictedDelaunay(d, rvd));
        qInfo("sphere: %d iterations (%s), RDT %d triangles, mean Q %.4f, min angle %.2f deg",
              r.iterations, r.stopReason.c_str(), q.triangles, q.meanQuality, q.minAngleDeg);
        QCOMPARE(q.triangles, 2 * 100 - 4); // a closed sphere: Euler
        QVERIFY(q.meanQuality >= 0.9);
        QVERIFY(q.minAngleDeg >= 30.0);
    }

    void lloydDecreasesEnergy()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        CvtParams params;
        params.iterations = 15;
        params.lloyd = true;
        const CvtResult r = optimizeCvt(d, sampleSurfaces(d, 60, 5), params);
        QCOMPARE(r.iterations, 15);
        verifyDecreasing(r);
    }

    // Fixed sites keep their place (to rounding: L-BFGS works on scaled coordinates) under L-BFGS
    // and Lloyd; the others still move and the energy still decreases.
    void fixedSitesStayWhereTheyAre()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        const std::vector<Vec3> initial = sampleSurfaces(d, 80, 11);
        for (const bool lloyd : {false, true}) {
            CvtParams params;
            params.iterations = 20;
            params.lloyd = lloyd;
            params.fixedSites.assign(initial.size(), 0);
            for (std::size_t i = 0; i < initial.size(); i += 4)
                params.fixedSites[i] = 1;
            const CvtResult r = optimizeCvt(d, initial, params);
            verifyDecreasing(r);
            int moved = 0;
            for (std::size_t i = 0; i < initial.size(); ++i) {
                if (params.fixedSites[i])
                    QVERIFY2((r.sites[i] - initial[i]).norm() < 1e-12,
                             qPrintable(QString("site %1").arg(i)));
                else
                    moved += (r.sites[i] - initial[i]).norm() > 1e-3;
            }
            QVERIFY2(moved >= 50, qPrintable(QString::number(moved))); // of the 60 free ones
        }
    }

    void sameSeedSameSitesWhateverTheThreads()
    {
        const RestrictionDomain d = test::squareDomain(30);
        const std::vector<Vec3> a = sampleSurfaces(d, 150, 7), b = sampleSurfaces(d, 150, 7);
        QVERIFY(a == b);
        QVERIFY(a != sampleSurfaces(d, 150, 8));
        CvtParams params;
        params.iterations = 20;
        params.alpha = 0.3;
        params.threads = 1;
        const CvtResult one = optimizeCvt(d, a, params);
        params.threads = 2;
        const CvtResult two = optimizeCvt(d, a, params);
        QCOMPARE(one.threads, 1);
        QCOMPARE(two.threads, 2);
        QVERIFY(one.sites == two.sites); // bitwise
        QVERIFY(one.energy == two.energy);
    }

    void nearestNeighbourSearchFollowsTheSamePath()
    {
        // Same exact diagrams, so the same optimisation up to rounding of the integrals.
        const RestrictionDomain d = test::sphereDomain(3);
        const std::vector<Vec3> initial = sampleSurfaces(d, 80, 13);
        CvtParams params;
        params.iterations = 8;
        const CvtResult delaunay = optimizeCvt(d, initial, params);
        params.neighbourSearch = NeighbourSearch::NearestNeighbours;
        const CvtResult nearest = optimizeCvt(d, initial, params);
        QCOMPARE(nearest.iterations, delaunay.iterations);
        for (std::size_t k = 0; k < delaunay.energy.size(); ++k)
            QVERIFY(std::abs(nearest.energy[k] - delaunay.energy[k]) <= 1e-9 * delaunay.energy[k]);
        params.threads = 1;
        const CvtResult one = optimizeCvt(d, initial, params);
        params.threads = 2;
        const CvtResult two = optimizeCvt(d, initial, params);
        QVERIFY(one.sites == two.sites);
    }

    void stopsAtGradientTolerance()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        CvtParams params;
        params.iterations = 200;
        params.gradientTolerance = 1e-3;
        const CvtResult r = optimizeCvt(d, sampleSurfaces(d, 40, 3), params);
        QVERIFY(r.iterations < 200);
        QCOMPARE(QString::fromStdString(r.stopReason), QString("gradient"));
        QVERIFY(r.gradientNorm.back() <= 1e-3);
    }

    void cancelStopsTheRun()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        Progress progress;
        CvtParams params;
        params.onIteration = [&](const CvtIterationReport &r) {
            if (r.iteration == 3)
                progress.cancel();
        };
        QVERIFY_THROWS_EXCEPTION(Cancelled,
                                 optimizeCvt(d, sampleSurfaces(d, 40, 3), params, progress));
    }

    void boundaryTermPullsSitesOntoLines()
    {
        const RestrictionDomain d = test::squareDomain(24);
        const std::vector<Vec3> initial = sampleSurfaces(d, 80, 11);
        CvtParams params;
        params.iterations = 60;
        const CvtResult plain = optimizeCvt(d, initial, params);
        // Balance for a border cell of size h: 2(d − h/2) + α/(1 − α)·d = 0, so d = h/6 at α = 0.8
        // against about h/2 without the boundary term.
        params.alpha = 0.8;
        const CvtResult pulled = optimizeCvt(d, initial, params);
        verifyDecreasing(pulled);
        const LineDistance before = distanceToLines(d, plain.sites),
                           after = distanceToLines(d, pulled.sites);
        qInfo(
            "distance of line sites to the border: mean %.4g -> %.4g, length-weighted %.4g -> %.4g",
            before.mean, after.mean, before.weighted, after.weighted);
        QVERIFY(after.mean < before.mean);
        QVERIFY(after.weighted < 0.5 * before.weighted);
    }

    void badParametersAreRejected()
    {
        const RestrictionDomain d = test::sphereDomain(1);
        CvtParams params;
        params.alpha = 1.5;
        QVERIFY_THROWS_EXCEPTION(InputError, optimizeCvt(d, sampleSurfaces(d, 5, 1), params));
        params.alpha = 0.5;
        params.lloyd = true;
        QVERIFY_THROWS_EXCEPTION(InputError, optimizeCvt(d, sampleSurfaces(d, 5, 1), params));
        QVERIFY_THROWS_EXCEPTION(InputError, optimizeCvt(d, {}, CvtParams{}));
        QVERIFY_THROWS_EXCEPTION(InputError, sampleSurfaces(d, 0, 1));
    }
};

QTEST_GUILESS_MAIN(TestCvtOptimizer)
#include "test_cvt_optimizer.moc"
