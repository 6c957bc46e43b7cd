// The tets of a comparison mesh in a VTK scene: every tet is drawn with its region and min
// dihedral angle, the clip plane keeps whole tets on one side (the same plane for both sides of
// a TetMeshPair), bad node ids are skipped, and clearing hides everything.
#include "tet_mesh_pair.h"
#include "tet_mesh_scene.h"

#include <QtTest>

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

using namespace stratamesh;

namespace {

// A row of n unit-ish tets along x, tet i in region i % 2, min dihedral 10 i degrees.
std::shared_ptr<const VolumeMesh> rowOfTets(int n, double xOffset = 0.0)
{
    auto mesh = std::make_shared<VolumeMesh>();
    mesh->regionNames = {"lower", "upper"};
    for (int i = 0; i < n; ++i) {
        const double x = xOffset + 2.0 * i;
        const int first = int(mesh->points.size());
        mesh->points.push_back(Vec3(x, 0, 0));
        mesh->points.push_back(Vec3(x + 1, 0, 0));
        mesh->points.push_back(Vec3(x, 1, 0));
        mesh->points.push_back(Vec3(x, 0, 1));
        mesh->cells.push_back(Cell::tet(first, first + 1, first + 2, first + 3));
        mesh->cellRegion.push_back(i % 2);
        mesh->cellQuality.push_back(10.0 * i);
    }
    return mesh;
}

} // namespace

class TestTetMeshScene : public QObject {
    Q_OBJECT
private slots:
    void drawsEveryTetAndClipsWholeTets()
    {
        vtkNew<vtkRenderer> renderer;
        TetMeshScene scene(renderer);
        QVERIFY(!scene.actor()->GetVisibility());
        scene.setMesh(rowOfTets(5)); // x in [0, 9]
        QCOMPARE(scene.tetCount(), 5);
        QCOMPARE(scene.shownTetCount(), 5);
        QVERIFY(scene.actor()->GetVisibility() && scene.scalarBar()->GetVisibility());
        double b[6];
        QVERIFY(scene.bounds(b));
        QCOMPARE(b[0], 0.0);
        QCOMPARE(b[1], 9.0);

        // Normal -x at x = 4.5: tets with a node at x > 4.5 are kept (tets 2, 3, 4; tet 2 spans
        // [4, 5] and crosses the plane, so it stays whole).
        const double origin[3] = {4.5, 0, 0}, normal[3] = {-1, 0, 0};
        scene.setClipPlane(origin, normal);
        QVERIFY(scene.isClipped());
        QCOMPARE(scene.shownTetCount(), 3);
        scene.clearClipPlane();
        QCOMPARE(scene.shownTetCount(), 5);

        scene.setColouring(TetColouring::MinDihedral);
        QCOMPARE(QString(scene.actor()->GetMapper()->GetArrayName()),
                 QStringLiteral("min_dihedral_deg"));
        scene.setColouring(TetColouring::Region);
        QCOMPARE(QString(scene.actor()->GetMapper()->GetArrayName()), QStringLiteral("region"));

        scene.setMesh(nullptr);
        QCOMPARE(scene.tetCount(), 0);
        QVERIFY(!scene.actor()->GetVisibility());
        QVERIFY(!scene.bounds(b));
    }

    void badNodesAreSkipped()
    {
        vtkNew<vtkRenderer> renderer;
        TetMeshScene scene(renderer);
        auto mesh = std::make_shared<VolumeMesh>(*rowOfTets(2));
        mesh->cells.push_back(Cell::tet(0, 1, 2, 99));
        mesh->cellRegion.push_back(0);
        mesh->cellQuality.push_back(1.0);
        scene.setMesh(mesh);
        QCOMPARE(scene.tetCount(), 2);
    }

    // One plane for both views, placed in the bounds of both meshes together.
    void pairClipsBothAtTheSamePlace()
    {
        vtkNew<vtkRenderer> left, right;
        TetMeshPair pair(left, right);
        pair.setMeshes(rowOfTets(3), rowOfTets(5)); // x in [0, 5] and [0, 9]
        pair.setClip(true, ClipAxis::X, 0.5);       // x = 4.5 in the common bounds
        QCOMPARE(pair.input().shownTetCount(), 1);  // tet 2 spans [4, 5]
        QCOMPARE(pair.output().shownTetCount(), 3);
        pair.setClip(false, ClipAxis::X, 0.5);
        QCOMPARE(pair.input().shownTetCount(), 3);
        // An input-only run: the plane follows the input alone.
        pair.setMeshes(rowOfTets(3), nullptr);
        pair.setClip(true, ClipAxis::X, 0.5); // x = 2.5
        QCOMPARE(pair.input().shownTetCount(), 2);
        QVERIFY(!pair.output().actor()->GetVisibility());
    }
};

QTEST_GUILESS_MAIN(TestTetMeshScene)
#include "test_tet_mesh_scene.moc"
