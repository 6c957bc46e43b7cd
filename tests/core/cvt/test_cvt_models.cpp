// The Voronoi engine on the thesis models (data): modelA2 at 1000 sites and modelA5 at 5000
// sites keep every site and every square metre, and the boundary term brings the sites that
// sample a contact or border line closer to it.
#include "cvt/cvt_optimizer.h"
#include "cvt/initial_sampling.h"
#include "io/model_reader.h"
#include "model/topology.h"
#include "quality/restricted_delaunay_quality.h"
#include "support/test_data.h"
#include "voronoi/restricted_voronoi.h"

#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

struct LineDistances {
    double mean = 0;     // over sites whose cell meets a line
    double weighted = 0; // weighted by the length of line in the cell
    int sites = 0;
};

double segmentDistance(const Vec3 &p, const Vec3 &a, const Vec3 &b)
{
    const Vec3 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (a + t * d - p).norm();
}

// Distance of each line-touching site to the lines its cell meets.
LineDistances lineDistances(const RestrictionDomain &domain, const RestrictedVoronoiDiagram &rvd)
{
    LineDistances r;
    double length = 0;
    for (std::size_t s = 0; s < rvd.cells.size(); ++s) {
        const RestrictedCell &cell = rvd.cells[s];
        if (cell.lineComponents.empty())
            continue;
        double best = 1e300;
        for (int c : cell.lineComponents) {
            const int line = rvd.lineComponents[c].line;
            for (int k = domain.lineOffsets[line]; k < domain.lineOffsets[line + 1]; ++k) {
                const auto &seg = domain.segments[domain.lineSegments[k]];
                best = std::min(best, segmentDistance(rvd.sites[s], domain.points[seg[0]],
                                                      domain.points[seg[1]]));
            }
        }
        r.mean += best;
        r.weighted += cell.length * best;
        length += cell.length;
        ++r.sites;
    }
    r.mean /= std::max(r.sites, 1);
    r.weighted /= std::max(length, 1e-300);
    return r;
}

void checkModel(const QString &path, int siteCount)
{
    const Model model = recoverTopology(readModel(path.toStdString()));
    const RestrictionDomain domain = makeRestrictionDomain(model);
    QVERIFY(!domain.segments.empty());
    const std::vector<Vec3> initial = sampleSurfaces(domain, siteCount, 2024);
    CvtParams params;
    params.iterations = 30;
    LineDistances distances[2];
    for (int run = 0; run < 2; ++run) {
        params.alpha = run == 0 ? 0.0 : 0.7;
        const CvtResult result = optimizeCvt(domain, initial, params);
        QCOMPARE(result.sites.size(), initial.size());
        for (std::size_t k = 1; k < result.energy.size(); ++k)
            QVERIFY(result.energy[k] <= result.energy[k - 1]);
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(domain, result.sites);
        int empty = 0;
        double area = 0, length = 0;
        for (const RestrictedCell &c : rvd.cells) {
            empty += !(c.area > 0);
            area += c.area;
            length += c.length;
        }
        QCOMPARE(empty, 0); // no site lost
        QVERIFY(std::abs(area - domain.surfaceArea()) <= 1e-9 * domain.surfaceArea());
        QVERIFY(std::abs(length - domain.lineLength()) <= 1e-9 * domain.lineLength());
        std::vector<int> corners;
        for (const RestrictedCell &c : rvd.cells)
            corners.insert(corners.end(), c.corners.begin(), c.corners.end());
        QCOMPARE(corners.size(), domain.corners.size());
        distances[run] = lineDistances(domain, rvd);
        const RestrictedDelaunayQuality q =
            restrictedDelaunayQuality(restrictedDelaunay(domain, rvd));
        qInfo("%s, %d sites, alpha %.1f: %d iterations, %.2f s (RVD %.2f s, Delaunay %.2f s); RDT "
              "mean Q %.3f, "
              "%.2f %% below 30 deg; line sites %d, mean distance %.4g, length-weighted %.4g",
              qPrintable(QFileInfo(path).fileName()), siteCount, params.alpha, result.iterations,
              result.totalSeconds, result.rvdSeconds, result.delaunaySeconds, q.meanQuality,
              q.percentAngleBelow30, distances[run].sites, distances[run].mean,
              distances[run].weighted);
    }
    QVERIFY(distances[1].mean < distances[0].mean);
    QVERIFY(distances[1].weighted < distances[0].weighted);
}

} // namespace

class TestCvtModels : public QObject {
    Q_OBJECT
private slots:
    void modelA2()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA2.ml");
        checkModel(path, 1000);
    }
    void modelA5()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA5.ml");
        checkModel(path, 5000);
    }
};

QTEST_GUILESS_MAIN(TestCvtModels)
#include "test_cvt_models.moc"
