// VTK export of complexity cells (core/io/cells_vtu_writer): read back with VTK's own reader.
#include "common/error.h"
#include "complexity/box_cvt.h"
#include "complexity/clipped_voronoi.h"
#include "io/cells_vtu_writer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Geometry>

using namespace stratamesh;

class TestCellsVtuWriter : public QObject {
    Q_OBJECT
private slots:
    void roundTrip()
    {
        const Box3 box(Vec3(1e6, 2e6, -500), Vec3(1e6 + 800, 2e6 + 600, 0));
        const std::vector<Vec3> sites = randomSitesInBox(box, 40, 3);
        const std::vector<ConvexPolyhedron> cells = clippedVoronoiCells(sites, box);
        CellIntArray counts{"total", {}};
        for (std::size_t i = 0; i < cells.size(); ++i)
            counts.values.push_back(static_cast<int>(i) * 7 % 5);
        QTemporaryDir dir;
        const std::string path = dir.filePath("cells.vtu").toStdString();
        writeCellsVtu(path, cells, {counts});

        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(path.c_str());
        reader->Update();
        vtkUnstructuredGrid *grid = reader->GetOutput();
        QCOMPARE(grid->GetNumberOfCells(), static_cast<vtkIdType>(cells.size()));
        auto *total = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("total"));
        auto *ids = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("CellId"));
        QVERIFY(total && ids);
        for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
            QCOMPARE(grid->GetCellType(c), VTK_POLYHEDRON);
            const int id = ids->GetValue(c);
            QCOMPARE(total->GetValue(c), counts.values[id]);
            // Volume from the face stream (divergence theorem): positive when faces point out.
            vtkNew<vtkIdList> stream;
            grid->GetFaceStream(c, stream);
            double volume = 0.0;
            vtkIdType k = 1;
            const Vec3 ref = cells[id].vertices().front();
            for (vtkIdType f = 0; f < stream->GetId(0); ++f) {
                const vtkIdType n = stream->GetId(k);
                auto point = [&](vtkIdType i) -> Vec3 {
                    double p[3];
                    grid->GetPoints()->GetPoint(stream->GetId(k + 1 + i), p);
                    return Vec3(p[0], p[1], p[2]) - ref;
                };
                for (vtkIdType i = 1; i + 1 < n; ++i)
                    volume += point(0).dot(point(i).cross(point(i + 1))) / 6.0;
                k += n + 1;
            }
            QVERIFY2(std::abs(volume - cells[id].volume()) < 1e-6 * cells[id].volume(),
                     qPrintable(QString("%1 vs %2").arg(volume).arg(cells[id].volume())));
        }
    }

    void badArrays()
    {
        const Box3 box(Vec3(0, 0, 0), Vec3(1, 1, 1));
        const std::vector<ConvexPolyhedron> cells =
            clippedVoronoiCells(randomSitesInBox(box, 4, 1), box);
        QTemporaryDir dir;
        QVERIFY_THROWS_EXCEPTION(
            InputError, writeCellsVtu(dir.filePath("x.vtu").toStdString(), cells, {{"n", {1, 2}}}));
        QVERIFY_THROWS_EXCEPTION(FileError, writeCellsVtu("/nonexistent-folder/x.vtu", cells, {}));
    }
};

QTEST_GUILESS_MAIN(TestCellsVtuWriter)
#include "test_cells_vtu_writer.moc"
