// The overlap test of two triangles sharing an edge must give the exact predicates' answer,
// including where its double-precision shortcut does not apply (folded, coplanar, needle).
#include "model/shared_edge_overlap.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <QtTest>

#include <random>

using namespace stratamesh;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

bool exactOverlap(const Vec3 &u, const Vec3 &v, const Vec3 &a, const Vec3 &b)
{
    const Kernel::Point_3 pu(u.x(), u.y(), u.z()), pv(v.x(), v.y(), v.z()), pa(a.x(), a.y(), a.z()),
        pb(b.x(), b.y(), b.z());
    return CGAL::orientation(pu, pv, pa, pb) == CGAL::COPLANAR
           && CGAL::coplanar_orientation(pu, pv, pa, pb) == CGAL::POSITIVE;
}

} // namespace

class TestSharedEdgeOverlap : public QObject {
    Q_OBJECT
private slots:
    void simpleCases()
    {
        const Vec3 u(0, 0, 0), v(2, 0, 0);
        QVERIFY(!sharedEdgeTrianglesOverlap(u, v, Vec3(1, 1, 0), Vec3(1, -1, 0))); // unfolded
        QVERIFY(sharedEdgeTrianglesOverlap(u, v, Vec3(1, 1, 0), Vec3(1, 2, 0)));   // folded
        QVERIFY(
            !sharedEdgeTrianglesOverlap(u, v, Vec3(1, 1, 0), Vec3(1, 1, 1e-9)));  // bent a little
        QVERIFY(!sharedEdgeTrianglesOverlap(u, v, Vec3(1, 1, 0), Vec3(1, 0, 1))); // at right angle
        // A needle apex on the edge's line: the exact predicates decide.
        QVERIFY(!sharedEdgeTrianglesOverlap(u, v, Vec3(1, 1, 0), Vec3(3, 0, 0)));
    }

    // Random pairs on exactly representable planes (axis planes and x + y + z = 8 on a grid of
    // quarters), and pairs bent out of the plane by tiny amounts: the same answer as the exact
    // predicates every time, with both answers occurring.
    void agreesWithExactPredicates()
    {
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> grid(-16, 16);
        std::uniform_real_distribution<double> tiny(-1e-12, 1e-12);
        auto onPlane = [&](int plane) {
            const double x = grid(rng) / 4.0, y = grid(rng) / 4.0;
            return plane == 0 ? Vec3(x, y, 1.5) : Vec3(x, y, 8.0 - x - y);
        };
        int overlaps = 0, separate = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            const int plane = trial % 2;
            const Vec3 u = onPlane(plane), v = onPlane(plane), a = onPlane(plane);
            Vec3 b = onPlane(plane);
            if (trial % 5 == 0)
                b += Vec3(tiny(rng), tiny(rng), tiny(rng));
            if (u == v)
                continue;
            const bool expected = exactOverlap(u, v, a, b);
            QCOMPARE(sharedEdgeTrianglesOverlap(u, v, a, b), expected);
            (expected ? overlaps : separate) += 1;
        }
        QVERIFY(overlaps > 1000);
        QVERIFY(separate > 1000);
    }
};

QTEST_APPLESS_MAIN(TestSharedEdgeOverlap)
#include "test_shared_edge_overlap.moc"
