// The tets of a comparison mesh in a VTK scene: every tet is drawn with its region and min
// dihedral angle, the clip plane keeps whole tets on one side (the same plane for both sides of
// a TetMeshPair), bad node ids are skipped, and clearing hides everything; a hybrid mesh's
// pyramids and prisms are drawn too, prisms in VTK_WEDGE's node order, and coloured by type.
#include "tet_mesh_pair.h"
#include "tet_mesh_scene.h"

#include <QtTest>

#include <vtkActor.h>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkUnstructuredGrid.h>

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
    void drawsPyramidsAndPrisms()
    {
        auto mesh = std::make_shared<VolumeMesh>();
        mesh->regionNames = {"layer"};
        // A unit prism (bottom 0 1 2, top 3 4 5) and a pyramid on the square x in [1, 2].
        mesh->points = {Vec3(0, 0, 0), Vec3(1, 0, 0),    Vec3(0, 1, 0), Vec3(0, 0, 1),
                        Vec3(1, 0, 1), Vec3(0, 1, 1),    Vec3(1, 1, 0), Vec3(2, 0, 0),
                        Vec3(2, 1, 0), Vec3(1.5, 0.5, 1)};
        mesh->cells = {Cell::prism(0, 1, 2, 3, 4, 5), Cell::pyramid(1, 7, 8, 6, 9),
                       Cell::tet(0, 1, 2, 3)};
        mesh->cellRegion = {0, 0, 0};
        mesh->cellQuality = {60.0, 45.0, 54.7};
        vtkNew<vtkRenderer> renderer;
        TetMeshScene scene(renderer);
        scene.setMesh(mesh);
        QCOMPARE(scene.tetCount(), 3);
        QCOMPARE(scene.cellCount(CellType::Prism), 1);
        QCOMPARE(scene.cellCount(CellType::Pyramid), 1);
        QCOMPARE(scene.cellCount(CellType::Tet), 1);
        vtkUnstructuredGrid *grid = scene.grid();
        QCOMPARE(grid->GetCellType(0), VTK_WEDGE);
        QCOMPARE(grid->GetCellType(1), VTK_PYRAMID);
        QCOMPARE(grid->GetCellType(2), VTK_TETRA);
        // The VTK writer's order (io/vtk_common.h): the bottom triangle turned the other way.
        vtkNew<vtkIdList> ids;
        grid->GetCellPoints(0, ids);
        const vtkIdType wedge[6] = {0, 2, 1, 3, 5, 4};
        for (int k = 0; k < 6; ++k)
            QCOMPARE(ids->GetId(k), wedge[k]);
        grid->GetCellPoints(1, ids);
        const vtkIdType pyramid[5] = {1, 7, 8, 6, 9};
        for (int k = 0; k < 5; ++k)
            QCOMPARE(ids->GetId(k), pyramid[k]);

        scene.setTypeTitles("Cell type", {"tet", "pyramid", "prism"});
        scene.setColouring(TetColouring::Type);
        auto *table = vtkLookupTable::SafeDownCast(scene.scalarBar()->GetLookupTable());
        QVERIFY(table);
        QCOMPARE(int(table->GetNumberOfAnnotatedValues()), 3);
        QCOMPARE(QString::fromStdString(table->GetAnnotation(2)), QStringLiteral("prism"));
        QCOMPARE(QString::fromUtf8(scene.scalarBar()->GetTitle()), QStringLiteral("Cell type"));
        double range[2];
        QVERIFY(scene.dihedralRange(range));
        QCOMPARE(range[0], 45.0);
        QCOMPARE(range[1], 60.0);
    }

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
