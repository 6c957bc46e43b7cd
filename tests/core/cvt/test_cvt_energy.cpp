// Gradients of F_CVT (thesis eq. 1.6) and F_B (eq. 4.1–4.3) against central finite differences
// on random configurations.
#include "core/voronoi/test_shapes.h"
#include "cvt/cvt_energy.h"

#include <QtTest>

#include <random>

using namespace stratamesh;

namespace {

double energyAt(const RestrictionDomain &d, const std::vector<Vec3> &sites, double alpha)
{
    CellIntegralsWorkspace ws;
    return evaluateCvtEnergy(d, sites, alpha, ws).energy;
}

// Largest relative error of the analytic gradient over a few random coordinates.
double worstRelativeError(const RestrictionDomain &d, const std::vector<Vec3> &sites, double alpha,
                          unsigned seed, double scale)
{
    CellIntegralsWorkspace ws;
    const CvtEvaluation e = evaluateCvtEnergy(d, sites, alpha, ws);
    std::mt19937 rng(seed);
    double worst = 0;
    int checked = 0;
    for (int trial = 0; trial < 200 && checked < 24; ++trial) {
        const int i = static_cast<int>(rng() % sites.size());
        const int c = static_cast<int>(rng() % 3);
        const double g = e.gradient[i][c];
        if (std::abs(g) < 1e-3 * e.gradientNorm() / std::sqrt(double(sites.size())))
            continue;                  // relative error of a near-zero component says nothing
        const double h = 1e-7 * scale; // central differences: truncation ∝ h², rounding ∝ 1/h
        std::vector<Vec3> plus = sites, minus = sites;
        plus[i][c] += h;
        minus[i][c] -= h;
        const double fd = (energyAt(d, plus, alpha) - energyAt(d, minus, alpha)) / (2 * h);
        worst = std::max(worst, std::abs(fd - g) / std::abs(g));
        ++checked;
    }
    if (checked < 10)
        return 1e300;
    return worst;
}

} // namespace

class TestCvtEnergy : public QObject {
    Q_OBJECT
private slots:
    void cvtGradientMatchesFiniteDifferences()
    {
        const RestrictionDomain d = test::sphereDomain(3);
        for (unsigned seed : {1u, 2u}) {
            const auto sites =
                test::randomPointsInBox(60, Vec3(-1.1, -1.1, -1.1), Vec3(1.1, 1.1, 1.1), seed);
            const double err = worstRelativeError(d, sites, 0.0, seed, 1.0);
            qInfo("F_CVT gradient: worst relative error %.3g", err);
            QVERIFY(err < 1e-5);
        }
    }

    void cvtGradientWithDensity()
    {
        RestrictionDomain d = test::squareDomain(12, false);
        d.density.resize(d.points.size());
        for (std::size_t i = 0; i < d.points.size(); ++i)
            d.density[i] = 1.0 + 2.0 * d.points[i].x() * d.points[i].y();
        finalizeDomain(d);
        const auto sites = test::randomPointsInBox(30, Vec3(0, 0, -0.1), Vec3(1, 1, 0.1), 9);
        const double err = worstRelativeError(d, sites, 0.0, 4, 1.0);
        QVERIFY(err < 1e-5);
    }

    void boundaryGradientMatchesFiniteDifferences()
    {
        const RestrictionDomain d = test::squareDomain(10);
        for (unsigned seed : {3u, 4u}) {
            const auto sites =
                test::randomPointsInBox(40, Vec3(-0.1, -0.1, -0.2), Vec3(1.1, 1.1, 0.2), seed);
            const double pure = worstRelativeError(d, sites, 1.0, seed, 1.0);
            const double blend = worstRelativeError(d, sites, 0.4, seed + 10, 1.0);
            qInfo("F_B gradient: worst relative error %.3g (alpha 1), %.3g (alpha 0.4)", pure,
                  blend);
            QVERIFY(pure < 1e-5);
            QVERIFY(blend < 1e-5);
        }
    }

    void energiesAreNonNegativeAndBlended()
    {
        const RestrictionDomain d = test::squareDomain(8);
        const auto sites = test::randomPointsInBox(20, Vec3(0, 0, -0.1), Vec3(1, 1, 0.1), 5);
        CellIntegralsWorkspace ws;
        const CvtEvaluation e = evaluateCvtEnergy(d, sites, 0.25, ws);
        QVERIFY(e.cvtEnergy > 0 && e.boundaryEnergy > 0);
        QVERIFY(std::abs(e.energy - (0.75 * e.cvtEnergy + 0.25 * e.boundaryEnergy))
                <= 1e-15 * e.energy);
    }

    // Evaluations reuse the neighbour lists while the sites move little; the diagram must stay
    // the exact one: energy and gradient identical to the bit with lists searched afresh.
    void reusedNeighbourListsGiveIdenticalEvaluations()
    {
        for (int shape = 0; shape < 2; ++shape) {
            const RestrictionDomain d = shape == 0 ? test::sphereDomain(3) : test::squareDomain(12);
            std::vector<Vec3> sites =
                shape == 0 ? test::randomPointsInBox(300, Vec3(-1, -1, -1), Vec3(1, 1, 1), 8)
                           : test::randomPointsInBox(150, Vec3(0, 0, -0.05), Vec3(1, 1, 0.05), 9);
            const double alpha = shape == 0 ? 0.0 : 0.3;
            CellIntegralsWorkspace shared;
            std::mt19937 rng(10 + shape);
            std::uniform_real_distribution<double> step(-2e-3, 2e-3);
            for (int k = 0; k < 12; ++k) {
                CellIntegralsWorkspace fresh;
                const CvtEvaluation a = evaluateCvtEnergy(d, sites, alpha, shared);
                const CvtEvaluation b = evaluateCvtEnergy(d, sites, alpha, fresh);
                QCOMPARE(a.energy, b.energy);
                QVERIFY(a.gradient == b.gradient);
                for (Vec3 &s : sites)
                    s += Vec3(step(rng), step(rng), step(rng));
                if (k == 8)
                    sites[0] += Vec3(0.3, 0.0, 0.0); // a jump: the lists must be searched again
            }
            QVERIFY2(shared.neighbourReuse.reuses >= 6, "small moves should reuse the lists");
            QVERIFY2(shared.neighbourReuse.searches >= 2, "the jump should force a new search");
        }
    }
};

QTEST_GUILESS_MAIN(TestCvtEnergy)
#include "test_cvt_energy.moc"
