// The heat map of the complexity cells (thesis Fig 3.7): which polyhedra and faces are drawn for
// a threshold, with which counts, and that bad input clears instead of drawing wrong cells.
#include "cell_heat_map.h"

#include <QtTest>

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

using namespace stratamesh;

namespace {

// The unit cube split at x = 0.5 into two cells that know each other by their face tags, plus
// a separate cube at x in [2, 3] touching nobody.
std::shared_ptr<const std::vector<ConvexPolyhedron>> threeCells()
{
    auto cells = std::make_shared<std::vector<ConvexPolyhedron>>();
    ConvexPolyhedron left = ConvexPolyhedron::box(Box3(Vec3(0, 0, 0), Vec3(1, 1, 1)));
    ConvexPolyhedron right = left;
    left.clip(HalfSpace{Vec3(1, 0, 0), 0.5, 1});    // x <= 0.5, across: cell 1
    right.clip(HalfSpace{Vec3(-1, 0, 0), -0.5, 0}); // x >= 0.5, across: cell 0
    cells->push_back(left);
    cells->push_back(right);
    cells->push_back(ConvexPolyhedron::box(Box3(Vec3(2, 0, 0), Vec3(3, 1, 1))));
    return cells;
}

std::vector<int> idsOf(vtkPolyData *poly)
{
    auto *ids = vtkIntArray::SafeDownCast(poly->GetCellData()->GetArray("CellId"));
    std::vector<int> out;
    for (vtkIdType k = 0; ids && k < ids->GetNumberOfTuples(); ++k)
        out.push_back(ids->GetValue(k));
    return out;
}

} // namespace

class TestCellHeatMap : public QObject {
    Q_OBJECT
private slots:
    void facesAndCellsFollowTheThreshold()
    {
        vtkNew<vtkRenderer> renderer;
        CellHeatMap map(renderer);
        QVERIFY(!map.hasCells());
        QVERIFY(!map.actor()->GetVisibility());
        const auto cells = threeCells();
        QCOMPARE((*cells)[0].faceCount(), 6);
        QCOMPARE((*cells)[1].faceCount(), 6);
        map.setThreshold(0);
        map.setCells(cells, {2, 5, 9});
        QCOMPARE(map.maxCount(), 9);
        QCOMPARE(map.shownCellCount(), 3);
        // The face between cells 0 and 1 is inside the drawn set: 5 + 5 + 6 faces.
        QCOMPARE(map.polyData()->GetNumberOfCells(), vtkIdType(16));
        QVERIFY(map.actor()->GetVisibility());
        QVERIFY(map.scalarBar()->GetVisibility());
        auto *counts = vtkIntArray::SafeDownCast(map.polyData()->GetCellData()->GetArray("count"));
        QVERIFY(counts);
        const std::vector<int> ids = idsOf(map.polyData());
        const int expected[] = {2, 5, 9};
        for (std::size_t k = 0; k < ids.size(); ++k)
            QCOMPARE(counts->GetValue(vtkIdType(k)), expected[ids[k]]);

        // Cell 0 filtered out: cell 1 shows its face towards it.
        map.setThreshold(3);
        QCOMPARE(map.shownCellCount(), 2);
        QCOMPARE(map.polyData()->GetNumberOfCells(), vtkIdType(12));
        for (int id : idsOf(map.polyData()))
            QVERIFY(id == 1 || id == 2);

        map.setThreshold(10);
        QCOMPARE(map.shownCellCount(), 0);
        QCOMPARE(map.polyData()->GetNumberOfCells(), vtkIdType(0));
        QVERIFY(!map.actor()->GetVisibility());
        QVERIFY(map.scalarBar()->GetVisibility()); // the scale still tells what exists

        map.setThreshold(0);
        map.setVisible(false);
        QVERIFY(!map.actor()->GetVisibility());
        QVERIFY(!map.scalarBar()->GetVisibility());
        map.setVisible(true);
        QVERIFY(map.actor()->GetVisibility());
    }

    // One colour per count, whatever the threshold.
    void coloursDoNotMoveWithTheThreshold()
    {
        vtkNew<vtkRenderer> renderer;
        CellHeatMap map(renderer);
        map.setCells(threeCells(), {2, 5, 40});
        auto *lut = vtkLookupTable::SafeDownCast(map.scalarBar()->GetLookupTable());
        QVERIFY(lut);
        double before[3], after[3];
        lut->GetColor(5.0, before);
        map.setThreshold(6);
        lut->GetColor(5.0, after);
        for (int k = 0; k < 3; ++k)
            QCOMPARE(after[k], before[k]);
        QCOMPARE(lut->GetTableRange()[1], 40.0);
        double low[3], high[3];
        lut->GetColor(1.0, low);
        lut->GetColor(40.0, high);
        QVERIFY(low[2] > low[0]);   // few elements: blue
        QVERIFY(high[0] > high[2]); // many: red
    }

    void mismatchedCountsClear()
    {
        vtkNew<vtkRenderer> renderer;
        CellHeatMap map(renderer);
        map.setThreshold(0);
        map.setCells(threeCells(), {1, 2}); // one count short
        QVERIFY(!map.hasCells());
        QCOMPARE(map.shownCellCount(), 0);
        QCOMPARE(map.polyData()->GetNumberOfCells(), vtkIdType(0));
        map.setCells(threeCells(), {1, 2, 3});
        QCOMPARE(map.shownCellCount(), 3);
        map.clear();
        QVERIFY(!map.hasCells());
        QCOMPARE(map.polyData()->GetNumberOfCells(), vtkIdType(0));
        QVERIFY(!map.actor()->GetVisibility());
        QVERIFY(!map.scalarBar()->GetVisibility());
    }
};

QTEST_GUILESS_MAIN(TestCellHeatMap)
#include "test_cell_heat_map.moc"
