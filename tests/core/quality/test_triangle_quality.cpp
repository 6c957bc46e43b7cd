// Hand-computed shapes: Q = 6S / (√3 · hmax · p), angles in degrees.
#include "quality/triangle_quality.h"

#include <QtTest>

#include <cmath>

using namespace stratamesh;

class TestTriangleQuality : public QObject {
    Q_OBJECT
private slots:
    void equilateral()
    {
        const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0);
        const TriangleShape s = triangleShape(a, b, c);
        QVERIFY(std::abs(s.quality - 1.0) < 1e-12);
        QVERIFY(std::abs(s.area - std::sqrt(3.0) / 4) < 1e-12);
        QVERIFY(std::abs(s.longestEdge - 1.0) < 1e-12);
        QVERIFY(std::abs(s.halfPerimeter - 1.5) < 1e-12);
        for (double angle : s.anglesDeg)
            QVERIFY(std::abs(angle - 60.0) < 1e-10);
    }

    void rightIsoceles()
    {
        // S = 1/2, hmax = √2, p = 1 + √2/2, so Q = 3 / (√6 + √3) ≈ 0.717439.
        const TriangleShape s = triangleShape(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
        QVERIFY(std::abs(s.quality - 3.0 / (std::sqrt(6.0) + std::sqrt(3.0))) < 1e-12);
        QVERIFY(std::abs(s.quality - 0.717439) < 1e-6);
        QVERIFY(std::abs(s.area - 0.5) < 1e-12);
        QVERIFY(std::abs(s.anglesDeg[0] - 90.0) < 1e-10);
        QVERIFY(std::abs(s.anglesDeg[1] - 45.0) < 1e-10);
        QVERIFY(std::abs(s.anglesDeg[2] - 45.0) < 1e-10);
        QVERIFY(std::abs(s.minAngleDeg - 45.0) < 1e-10);
        QVERIFY(std::abs(s.maxAngleDeg - 90.0) < 1e-10);
    }

    void threeFourFive()
    {
        // S = 6, hmax = 5, p = 6: Q = 36 / (30√3) ≈ 0.692820; smallest angle atan(3/4).
        const TriangleShape s = triangleShape(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 3, 0));
        QVERIFY(std::abs(s.quality - 1.2 / std::sqrt(3.0)) < 1e-12);
        QVERIFY(std::abs(s.minAngleDeg - 36.86989764584402) < 1e-9);
        QVERIFY(std::abs(s.anglesDeg[0] + s.anglesDeg[1] + s.anglesDeg[2] - 180.0) < 1e-9);
    }

    void invariantUnderSimilarity()
    {
        const Vec3 a(0, 0, 0), b(4, 0, 0), c(1, 2, 0);
        const Vec3 shift(1e5, -2e5, 3e3);
        const double q = triangleQuality(a, b, c);
        // Scaled by 250, rotated (x,y,z) -> (z,x,y), moved far from the origin as real models are.
        auto map = [&](const Vec3 &p) {
            Vec3 q(250 * p.z(), 250 * p.x(), 250 * p.y());
            q += shift;
            return q;
        };
        QVERIFY(std::abs(triangleQuality(map(a), map(b), map(c)) - q) < 1e-9);
        QVERIFY(std::abs(triangleMinAngleDeg(map(a), map(b), map(c)) - triangleMinAngleDeg(a, b, c))
                < 1e-7);
        QVERIFY(std::abs(triangleArea(map(a), map(b), map(c)) - 250.0 * 250.0 * 4.0) < 1e-3);
    }

    void needleKeepsItsTinyAngle()
    {
        // Half-angle at a is atan(1e-7 / 0.5): acos-based formulas return 0 here.
        const TriangleShape s = triangleShape(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-7, 0));
        const double expected = std::atan(2e-7) * 180.0 / M_PI;
        QVERIFY(s.minAngleDeg > 0.0);
        QVERIFY(std::abs(s.minAngleDeg - expected) < 1e-6 * expected);
        QVERIFY(s.quality > 0.0 && s.quality < 1e-6);
    }

    void degenerateIsZeroNotNaN()
    {
        const TriangleShape collinear = triangleShape(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0));
        QCOMPARE(collinear.quality, 0.0);
        QCOMPARE(collinear.area, 0.0);
        QCOMPARE(collinear.minAngleDeg, 0.0);
        QVERIFY(std::abs(collinear.maxAngleDeg - 180.0) < 1e-12);

        const Vec3 p(2, 2, 2);
        const TriangleShape point = triangleShape(p, p, p);
        QCOMPARE(point.quality, 0.0);
        QCOMPARE(point.minAngleDeg, 0.0);
        QVERIFY(!std::isnan(point.maxAngleDeg));
    }
};

QTEST_GUILESS_MAIN(TestTriangleQuality)
#include "test_triangle_quality.moc"
