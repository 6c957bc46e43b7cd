// Fins along contact lines dropped by flipping their long edge (line_fins.h).
#include "quality/triangle_quality.h"
#include "remesh/line_fins.h"

#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

OutputPoint point(double x, double y, std::vector<int> lines)
{
    OutputPoint p;
    p.position = Vec3(x, y, 0.0);
    p.surfaces = {0};
    p.lines = std::move(lines);
    return p;
}

double widestAngle(const EditableSoup &soup)
{
    double widest = 0.0;
    for (int t = 0; t < soup.triangleCapacity(); ++t)
        if (soup.alive(t)) {
            const OutputTriangle &tri = soup.triangle(t);
            widest =
                std::max(widest, triangleShape(soup.position(tri.v[0]), soup.position(tri.v[1]),
                                               soup.position(tri.v[2]))
                                     .maxAngleDeg);
        }
    return widest;
}

int aliveTriangles(const EditableSoup &soup)
{
    int n = 0;
    for (int t = 0; t < soup.triangleCapacity(); ++t)
        n += soup.alive(t) ? 1 : 0;
    return n;
}

} // namespace

class TestLineFins : public QObject {
    Q_OBJECT

private slots:
    // p, m, q along line 0 with m just off the chord: the fin (p, m, q) and the surface's
    // triangle (p, q, x) become (p, m, x) and (m, q, x).
    void finFlippedOntoTheLine()
    {
        OutputMesh mesh;
        mesh.points = {point(0, 0, {0}), point(1, 0.02, {0}), point(2, 0, {0}), point(1, -1, {})};
        mesh.triangles = {{{0, 1, 2}, 0}, {{0, 2, 3}, 0}};
        EditableSoup soup(std::move(mesh));
        QVERIFY(widestAngle(soup) > 170.0);
        QCOMPARE(removeLineFins(soup), 1);
        QCOMPARE(aliveTriangles(soup), 2);
        QVERIFY(widestAngle(soup) < 120.0);
        QCOMPARE(soup.edgeTriangles(1, 3).size(), std::size_t(2));
        QVERIFY(soup.edgeTriangles(0, 2).empty());
    }

    // Four points of one line hold a surface between them (a fault piece narrower than a cell):
    // either diagonal leaves a fin. Flipping back and forth never ended and ran out of memory;
    // only a flip that narrows the widest angle is made.
    void fourPointsOfOneLineEnd()
    {
        OutputMesh mesh;
        mesh.points = {point(0, 0, {0}), point(1, 0.15, {0}), point(2, 0.2, {0}),
                       point(3, 0.15, {0})};
        mesh.triangles = {{{0, 1, 2}, 0}, {{0, 2, 3}, 0}};
        EditableSoup soup(std::move(mesh));
        const double before = widestAngle(soup);
        QVERIFY(before > 150.0);
        const int removed = removeLineFins(soup);
        QVERIFY(removed <= 1);
        QCOMPARE(aliveTriangles(soup), 2);
        QVERIFY(widestAngle(soup) <= before);
    }
};

QTEST_GUILESS_MAIN(TestLineFins)
#include "test_line_fins.moc"
