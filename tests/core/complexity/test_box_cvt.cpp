// Clipped Voronoi cells and Lloyd's volumetric CVT in a box.
#include "common/error.h"
#include "complexity/box_cvt.h"
#include "complexity/clipped_voronoi.h"

#include <QtTest>

using namespace stratamesh;

class TestBoxCvt : public QObject {
    Q_OBJECT
private slots:
    void cellsTileTheBox()
    {
        const Box3 box(Vec3(-10, 0, 5), Vec3(30, 20, 15));
        const std::vector<Vec3> sites = randomSitesInBox(box, 500, 11);
        const std::vector<ConvexPolyhedron> cells = clippedVoronoiCells(sites, box);
        QCOMPARE(cells.size(), sites.size());
        double volume = 0.0;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            QVERIFY(!cells[i].empty());
            QVERIFY(cells[i].contains(sites[i]));
            volume += cells[i].volume();
            // A face tagged j is the bisector with site j: its vertices are equidistant.
            for (int f = 0; f < cells[i].faceCount(); ++f) {
                const int j = cells[i].facePlane(f).tag;
                if (j < 0)
                    continue;
                const Vec3 &v = cells[i].vertices()[*cells[i].faceBegin(f)];
                QVERIFY(std::abs((v - sites[i]).norm() - (v - sites[j]).norm()) < 1e-8);
                bool mutual = false; // and cell j has the face back
                for (int g = 0; g < cells[j].faceCount(); ++g)
                    mutual |= cells[j].facePlane(g).tag == static_cast<int>(i);
                QVERIFY(mutual);
            }
        }
        QVERIFY(std::abs(volume - box.volume()) < 1e-9 * box.volume());
    }

    void lloydDecreasesEnergy()
    {
        const Box3 box(Vec3(0, 0, 0), Vec3(4, 2, 1));
        BoxCvtParams params;
        params.sites = 300;
        params.iterations = 15;
        params.seed = 5;
        const BoxCvt cvt = runBoxCvt(box, params);
        QCOMPARE(cvt.iterations, 15);
        QCOMPARE(static_cast<int>(cvt.energy.size()), 16);
        for (std::size_t k = 1; k < cvt.energy.size(); ++k)
            QVERIFY(cvt.energy[k] <= cvt.energy[k - 1] * (1 + 1e-12));
        QVERIFY(cvt.energy.back() < 0.8 * cvt.energy.front());
        // Near a CVT the sites sit close to their cell centroids.
        double drift = 0.0;
        for (std::size_t i = 0; i < cvt.sites.size(); ++i)
            drift = std::max(drift, (cvt.cells[i].centroid() - cvt.sites[i]).norm());
        QVERIFY(drift < 0.1 * std::cbrt(box.volume() / params.sites));
        QVERIFY(std::abs(cvtEnergy(cvt.sites, cvt.cells) - cvt.energy.back()) < 1e-12);
    }

    void sameSeedSameSites()
    {
        const Box3 box(Vec3(0, 0, 0), Vec3(1, 1, 1));
        BoxCvtParams params;
        params.sites = 200;
        params.iterations = 5;
        params.seed = 42;
        const BoxCvt a = runBoxCvt(box, params);
        const BoxCvt b = runBoxCvt(box, params);
        QVERIFY(a.sites == b.sites);
        params.seed = 43;
        const BoxCvt c = runBoxCvt(box, params);
        QVERIFY(a.sites != c.sites);
    }

    void badInput()
    {
        const Box3 box(Vec3(0, 0, 0), Vec3(1, 1, 1));
        QVERIFY_THROWS_EXCEPTION(
            InputError, clippedVoronoiCells({Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5)}, box));
        BoxCvtParams params;
        params.sites = 0;
        QVERIFY_THROWS_EXCEPTION(InputError, runBoxCvt(box, params));
        params.sites = 10;
        QVERIFY_THROWS_EXCEPTION(InputError, runBoxCvt(Box3(Vec3(0, 0, 0), Vec3(1, 1, 0)), params));
        // A single site owns the whole box.
        const auto one = clippedVoronoiCells({Vec3(0.2, 0.3, 0.4)}, box);
        QVERIFY(std::abs(one[0].volume() - 1.0) < 1e-12);
    }
};

QTEST_GUILESS_MAIN(TestBoxCvt)
#include "test_box_cvt.moc"
