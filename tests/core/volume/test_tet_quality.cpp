// Tet shape measures: hand-computed values, and VTK's vtkMeshQuality (Verdict) on the same tets,
// random ones and a TetGen mesh, at 1e-9 relative.
//
// VTK 9.1's TetMinAngle (Verdict tet_minimum_angle) takes the angle between two face normals of
// which, for edges 02 and 13, one points in and one out: it returns min(θ01, 180 - θ02, θ03, θ12,
// 180 - θ13, θ23), not the minimum dihedral angle. Our angles are checked against exactly that,
// and over all 24 vertex orders its minimum is min(min dihedral, 180 - max dihedral).
#include "tetgen_test_models.h"
#include "volume/tet_quality.h"
#include "volume/tetgen_runner.h"

#include <vtkIdList.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkTetra.h>

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

struct VtkFigures {
    double radiusRatio, aspectRatio, minDihedralDeg, volume;
};

VtkFigures vtkFigures(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    vtkNew<vtkTetra> tet;
    const Vec3 *p[4] = {&a, &b, &c, &d};
    for (int k = 0; k < 4; ++k) {
        tet->GetPoints()->SetPoint(k, p[k]->x(), p[k]->y(), p[k]->z());
        tet->GetPointIds()->SetId(k, k);
    }
    return {vtkMeshQuality::TetRadiusRatio(tet), vtkMeshQuality::TetAspectRatio(tet),
            vtkMeshQuality::TetMinAngle(tet), vtkMeshQuality::TetVolume(tet)};
}

bool close(double ours, double theirs, double relative)
{
    return std::abs(ours - theirs) <= relative * std::max(std::abs(ours), std::abs(theirs));
}

// Fails with the measure's name and both values.
#define COMPARE_REL(ours, theirs, what)                                                            \
    QVERIFY2(close(ours, theirs, 1e-9), qPrintable(QStringLiteral("%1: ours %2, VTK %3")           \
                                                       .arg(what)                                  \
                                                       .arg(ours, 0, 'g', 17)                      \
                                                       .arg(theirs, 0, 'g', 17)))

// What VTK 9.1 calls the minimum angle, from our dihedral angles (see the top of this file).
double verdictMinAngle(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    const std::array<double, 6> t = dihedralAnglesDeg(a, b, c, d); // ab ac ad bc bd cd
    return std::min({t[0], 180.0 - t[1], t[2], t[3], 180.0 - t[4], t[5]});
}

void compareWithVtk(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    const TetQuality q = tetQuality(a, b, c, d);
    const VtkFigures v = vtkFigures(a, b, c, d);
    COMPARE_REL(q.radiusRatio, v.radiusRatio, "radius ratio");
    COMPARE_REL(q.aspectRatio, v.aspectRatio, "aspect ratio");
    COMPARE_REL(q.volume, v.volume, "volume");
    COMPARE_REL(verdictMinAngle(a, b, c, d), v.minDihedralDeg, "VTK min angle");
    // Every edge takes every slot in some vertex order.
    std::array<const Vec3 *, 4> p{&a, &b, &c, &d};
    std::sort(p.begin(), p.end());
    double lowest = 180.0;
    do
        lowest = std::min(lowest, vtkFigures(*p[0], *p[1], *p[2], *p[3]).minDihedralDeg);
    while (std::next_permutation(p.begin(), p.end()));
    COMPARE_REL(std::min(q.minDihedralDeg, 180.0 - q.maxDihedralDeg), lowest,
                "min and max dihedral");
}

} // namespace

class TestTetQuality : public QObject {
    Q_OBJECT

private slots:
    void handValues()
    {
        // Regular tet: every dihedral is acos(1/3), ratios 1.
        const double s = std::sqrt(2.0);
        const TetQuality r = tetQuality({s, 0, -1}, {-s, 0, -1}, {0, s, 1}, {0, -s, 1});
        QVERIFY(std::abs(std::abs(r.volume) - 8.0 / 3.0) < 1e-12); // edge 2√2
        QVERIFY(std::abs(r.radiusRatio - 1.0) < 1e-12);
        QVERIFY(std::abs(r.aspectRatio - 1.0) < 1e-12);
        const double regular = std::acos(1.0 / 3.0) * 180 / M_PI;
        QVERIFY(std::abs(r.minDihedralDeg - regular) < 1e-12);
        QVERIFY(std::abs(r.maxDihedralDeg - regular) < 1e-12);
        // Corner tet: three right dihedrals at the origin's edges, three of acos(1/√3).
        const TetQuality c = tetQuality({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
        QVERIFY(std::abs(c.volume - 1.0 / 6.0) < 1e-15);
        QVERIFY(std::abs(c.maxDihedralDeg - 90.0) < 1e-12);
        QVERIFY(std::abs(c.minDihedralDeg - std::acos(1 / std::sqrt(3.0)) * 180 / M_PI) < 1e-12);
        QVERIFY(std::abs(c.radiusRatio - 1.3660254037844386) < 1e-12); // (1 + √3) / 2
        // Inverted: same shape, negative volume.
        const TetQuality inv = tetQuality({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1});
        QVERIFY(std::abs(inv.volume + 1.0 / 6.0) < 1e-15);
        QVERIFY(std::abs(inv.radiusRatio - c.radiusRatio) < 1e-12);
        // Flat (formats.md §5.2 table): a sliver of 1.9° with huge ratios.
        const TetQuality f = tetQuality({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 0.01});
        QVERIFY(std::abs(f.minDihedralDeg - 1.909) < 1e-3);
        QVERIFY(std::abs(f.aspectRatio - 57.75) < 1e-2);
        QVERIFY(std::abs(f.radiusRatio - 1401) < 1);
        QVERIFY(f.maxDihedralDeg > 170);
        // Degenerate: infinite ratios, zero dihedral.
        const TetQuality z = tetQuality({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0});
        QCOMPARE(z.volume, 0.0);
        QVERIFY(std::isinf(z.radiusRatio) && std::isinf(z.aspectRatio));
        QCOMPARE(z.minDihedralDeg, 0.0);
    }

    void equalsVtkOnRandomTets()
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)),
                c(u(rng), u(rng), u(rng)), d(u(rng), u(rng), u(rng));
            // VTK's acos loses digits near 0° and 180°.
            const TetQuality q = tetQuality(a, b, c, d);
            if (q.minDihedralDeg < 1.0 || q.maxDihedralDeg > 179.0)
                continue;
            compareWithVtk(a, b, c, d);
            if (QTest::currentTestFailed())
                return;
        }
    }

    void equalsVtkOnTetgenTets()
    {
        const TetgenResult r = runTetgen(twoRegionBox(), {});
        QCOMPARE(tetgenOutcomeName(r.outcome), "ok");
        const VolumeMesh &m = r.mesh;
        for (const Cell &c : m.cells) {
            compareWithVtk(m.points[c.nodes[0]], m.points[c.nodes[1]], m.points[c.nodes[2]],
                           m.points[c.nodes[3]]);
            if (QTest::currentTestFailed())
                return;
        }
    }

    void statistics()
    {
        VolumeMesh m;
        m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, 0.01}, {5, 5, 5}};
        m.cells = {Cell::tet(0, 1, 2, 3), Cell::tet(0, 1, 2, 4)};
        m.cellRegion = {0, 0};
        const VolumeQualityStatistics s = volumeQuality(m);
        QCOMPARE(s.tets, std::size_t(2));
        QCOMPARE(s.points, std::size_t(5));
        QCOMPARE(s.slivers, std::size_t(1));
        QCOMPARE(s.flat, std::size_t(0));
        QVERIFY(std::abs(s.minDihedralDeg - 1.909) < 1e-3);
        QVERIFY(std::abs(s.totalVolume - (1.0 / 6 + 0.01 / 6)) < 1e-15);
        QVERIFY(std::abs(
                    s.meanRadiusRatio
                    - (tetQuality(m.points[0], m.points[1], m.points[2], m.points[3]).radiusRatio
                       + tetQuality(m.points[0], m.points[1], m.points[2], m.points[4]).radiusRatio)
                          / 2)
                < 1e-9);
        QCOMPARE(s.minDihedral.total(), std::size_t(2));
        QCOMPARE(s.minDihedral.counts()[0], std::size_t(1)); // the sliver bin
        QCOMPARE(s.inverseRadiusRatio.total(), std::size_t(2));
        // An empty mesh: zeros, no NaN.
        const VolumeQualityStatistics e = volumeQuality(VolumeMesh{});
        QCOMPARE(e.tets, std::size_t(0));
        QCOMPARE(e.minDihedralDeg, 0.0);
        QCOMPARE(e.meanRadiusRatio, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestTetQuality)
#include "test_tet_quality.moc"
