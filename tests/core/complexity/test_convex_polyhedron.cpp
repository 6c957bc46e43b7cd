// Convex polyhedron clipping: volumes, centroids, moments and face consistency after cuts.
#include "complexity/convex_clip.h"
#include "complexity/convex_polyhedron.h"

#include <QtTest>

#include <map>
#include <random>

using namespace stratamesh;

namespace {

ConvexPolyhedron unitCube()
{
    return ConvexPolyhedron::box(Box3(Vec3(0, 0, 0), Vec3(1, 1, 1)));
}

// Every edge is used once in each direction and every face is planar on its own plane.
bool isClosedAndPlanar(const ConvexPolyhedron &p)
{
    std::map<std::pair<int, int>, int> directed;
    for (int f = 0; f < p.faceCount(); ++f) {
        const int *loop = p.faceBegin(f);
        const int n = p.faceSize(f);
        const HalfSpace &h = p.facePlane(f);
        for (int i = 0; i < n; ++i) {
            if (std::abs(h.normal.dot(p.vertices()[loop[i]]) - h.offset) > 1e-9)
                return false;
            ++directed[{loop[i], loop[(i + 1) % n]}];
        }
    }
    for (const auto &[edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) != 1)
            return false;
    return true;
}

} // namespace

class TestConvexPolyhedron : public QObject {
    Q_OBJECT
private slots:
    void boxMeasures()
    {
        const ConvexPolyhedron p = ConvexPolyhedron::box(Box3(Vec3(1, 2, 3), Vec3(3, 5, 7)));
        QCOMPARE(p.faceCount(), 6);
        QVERIFY(isClosedAndPlanar(p));
        QVERIFY(std::abs(p.volume() - 24.0) < 1e-12);
        QVERIFY((p.centroid() - Vec3(2, 3.5, 5)).norm() < 1e-12);
        // ∫|x − c|² over a 2×3×4 box = V (a² + b² + c²) / 12.
        QVERIFY(std::abs(p.secondMoment(Vec3(2, 3.5, 5)) - 24.0 * (4 + 9 + 16) / 12.0) < 1e-9);
        for (int f = 0; f < 6; ++f) { // outward normals
            const HalfSpace &h = p.facePlane(f);
            QVERIFY(h.normal.dot(p.centroid()) < h.offset);
        }
    }

    void halfCut()
    {
        ConvexPolyhedron p = unitCube();
        QVERIFY(p.clip({Vec3(1, 1, 1), 1.5, 7}));
        QVERIFY(isClosedAndPlanar(p));
        QVERIFY(std::abs(p.volume() - 0.5) < 1e-12); // the plane x+y+z = 1.5 halves the cube
        QCOMPARE(p.faceCount(), 7);                  // hexagonal cap
        QCOMPARE(p.facePlane(6).tag, 7);
        QVERIFY(!p.clip({Vec3(1, 0, 0), 2.0, 8})); // beyond: unchanged
        ConvexPolyhedron q = unitCube();
        QVERIFY(q.clip({Vec3(1, 0, 0), -1.0, 9}));
        QVERIFY(q.empty());
    }

    void cutThroughEdgeAndVertices()
    {
        // The plane x = y passes through two edges of the cube: vertices on it stay, not split.
        ConvexPolyhedron p = unitCube();
        QVERIFY(p.clip({Vec3(1, -1, 0), 0.0, 1}));
        QVERIFY(isClosedAndPlanar(p));
        QVERIFY(std::abs(p.volume() - 0.5) < 1e-12);
        QCOMPARE(static_cast<int>(p.vertices().size()), 6); // triangular prism
        QCOMPARE(p.faceCount(), 5);
        // Through a vertex only: the corner tetrahedron x+y+z <= 1 has volume 1/6.
        ConvexPolyhedron t = unitCube();
        t.clip({Vec3(1, 1, 1), 1.0, 2});
        QVERIFY(isClosedAndPlanar(t));
        QVERIFY(std::abs(t.volume() - 1.0 / 6.0) < 1e-12);
        QVERIFY((t.centroid() - Vec3(0.25, 0.25, 0.25)).norm() < 1e-12);
    }

    void randomCutsConserveVolume()
    {
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int trial = 0; trial < 200; ++trial) {
            ConvexPolyhedron p = unitCube();
            for (int k = 0; k < 6; ++k) {
                const Vec3 n(u(rng), u(rng), u(rng));
                const Vec3 through = Vec3(0.5, 0.5, 0.5) + 0.3 * Vec3(u(rng), u(rng), u(rng));
                const HalfSpace h{n, n.dot(through), k};
                ConvexPolyhedron a = p;
                ConvexPolyhedron b = p;
                a.clip(h);
                b.clip({-n, -h.offset, k});
                QVERIFY(std::abs(a.volume() + b.volume() - p.volume()) < 1e-12);
                if (!a.empty())
                    QVERIFY(isClosedAndPlanar(a));
                if (!b.empty())
                    QVERIFY(isClosedAndPlanar(b));
                p = a.empty() ? b : a;
            }
            for (const Vec3 &v : p.vertices())
                QVERIFY(p.contains(v));
        }
    }

    void segmentsAndTriangles()
    {
        ConvexPolyhedron p = unitCube();
        p.clip({Vec3(1, 1, 1), 1.5, 0});
        QVERIFY(segmentMeetsCell(Vec3(-1, 0.2, 0.2), Vec3(2, 0.2, 0.2), p));
        QVERIFY(!segmentMeetsCell(Vec3(0.9, 0.9, 0.9), Vec3(2, 2, 2), p));
        QVERIFY(!segmentMeetsCell(Vec3(-1, 2, 0.5), Vec3(2, 2, 0.5), p));
        // A large triangle crossing the cell with no vertex inside it.
        QVERIFY(triangleMeetsCell(Vec3(-5, -5, 0.3), Vec3(5, -5, 0.3), Vec3(0, 5, 0.3), p));
        // Inside the cube but beyond the cap plane x + y + z = 1.5: no.
        QVERIFY(!triangleMeetsCell(Vec3(0.7, 0.7, 0.9), Vec3(1, 0.7, 0.9), Vec3(0.7, 1, 0.9), p));
        // On the cube's top face, where the cell still reaches (x + y <= 0.5): touching counts.
        QVERIFY(triangleMeetsCell(Vec3(-5, -5, 1.0), Vec3(5, -5, 1.0), Vec3(0.8, 0.8, 1.0), p));
        const std::vector<Vec3> piece = clipPolygonToCell(
            {Vec3(-1, -1, 0.25), Vec3(2, -1, 0.25), Vec3(2, 2, 0.25), Vec3(-1, 2, 0.25)}, p);
        // The square section z = 0.25 of the cube, cut by x + y <= 1.25: a pentagon of area 1 −
        // 0.5·0.75².
        double area = 0.0;
        for (std::size_t i = 1; i + 1 < piece.size(); ++i)
            area += 0.5 * (piece[i] - piece[0]).cross(piece[i + 1] - piece[0]).norm();
        QVERIFY(std::abs(area - (1.0 - 0.5 * 0.75 * 0.75))
                < 1e-8); // planes pushed out by the tolerance
    }
};

QTEST_GUILESS_MAIN(TestConvexPolyhedron)
#include "test_convex_polyhedron.moc"
