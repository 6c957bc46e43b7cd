// The bounding-box diagonal shared by the close-vertex check, the remesher's d_resolution bound
// and the Hausdorff distance: hand-computed values on points and models built here.
#include "model/bounding_box.h"

#include <QtTest>

using namespace stratamesh;

class TestBoundingBox : public QObject {
    Q_OBJECT

private slots:
    void diagonalOfPoints()
    {
        QCOMPARE(boundingBoxDiagonal(std::vector<Vec3>{}), 0.0);
        QCOMPARE(boundingBoxDiagonal({Vec3(1, 2, 3)}), 0.0);
        // Box 3 × 4 × 12 from the extremes of several points: diagonal 13.
        QCOMPARE(boundingBoxDiagonal({Vec3(0, 1, 0), Vec3(3, 0, 5), Vec3(1, 4, 12), Vec3(2, 2, 2)}),
                 13.0);
        QCOMPARE(boundingBoxDiagonal({Vec3(-3, -4, -12), Vec3(0, 0, 0)}), 13.0);
    }

    // Over every surface vertex, topology or not.
    void diagonalOfModel()
    {
        Model m;
        QCOMPARE(boundingBoxDiagonal(m), 0.0);
        Surface a, b;
        a.vertices = {Vec3(0, 0, 0), Vec3(3, 0, 0)};
        b.vertices = {Vec3(0, 4, 0), Vec3(1, 1, 12)};
        m.surfaces = {a, b};
        QCOMPARE(boundingBoxDiagonal(m), 13.0);
        QVERIFY(m.vertices.empty());
    }
};

QTEST_APPLESS_MAIN(TestBoundingBox)
#include "test_bounding_box.moc"
