#include "io/cells_vtu_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/vtk_common.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkErrorCode.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace stratamesh {

namespace {

vtkNew<vtkUnstructuredGrid> makeGrid(const std::vector<ConvexPolyhedron> &cells,
                                     const std::vector<CellIntArray> &arrays)
{
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble(); // real coordinates (~1e6) lose digits in float
    std::vector<vtkSmartPointer<vtkIntArray>> data;
    auto cellId = vtkSmartPointer<vtkIntArray>::New();
    cellId->SetName("CellId");
    for (const CellIntArray &a : arrays) {
        auto array = vtkSmartPointer<vtkIntArray>::New();
        array->SetName(a.name.c_str());
        data.push_back(array);
    }
    std::vector<vtkIdType> ids;
    std::vector<vtkIdType> faces;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const ConvexPolyhedron &cell = cells[c];
        if (cell.empty())
            continue;
        ids.clear();
        for (const Vec3 &p : cell.vertices())
            ids.push_back(points->InsertNextPoint(p.x(), p.y(), p.z()));
        // Face stream: n, then its point ids, per face; loops are counter-clockwise from outside.
        faces.clear();
        for (int f = 0; f < cell.faceCount(); ++f) {
            faces.push_back(cell.faceSize(f));
            for (int k = 0; k < cell.faceSize(f); ++k)
                faces.push_back(ids[cell.faceBegin(f)[k]]);
        }
        grid->InsertNextCell(VTK_POLYHEDRON, static_cast<vtkIdType>(ids.size()), ids.data(),
                             cell.faceCount(), faces.data());
        cellId->InsertNextValue(static_cast<int>(c));
        for (std::size_t a = 0; a < arrays.size(); ++a)
            data[a]->InsertNextValue(arrays[a].values[c]);
    }
    grid->SetPoints(points);
    grid->GetCellData()->AddArray(cellId);
    for (const auto &array : data)
        grid->GetCellData()->AddArray(array);
    return grid;
}

} // namespace

void writeCellsVtu(const std::string &path, const std::vector<ConvexPolyhedron> &cells,
                   const std::vector<CellIntArray> &arrays)
{
    for (const CellIntArray &a : arrays)
        if (a.values.size() != cells.size())
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "cells export: array '%1' has %2 values for %3 cells"),
                {a.name, std::to_string(a.values.size()), std::to_string(cells.size())}});
    vtkNew<vtkUnstructuredGrid> grid = makeGrid(cells, arrays);
    writeFileAtomically(path, [&](const std::string &temporary) {
        vtkNew<vtkXMLUnstructuredGridWriter> writer;
        VtkErrorCapture errors(writer);
        writer->SetInputData(grid);
        writer->SetDataModeToBinary();
        writer->SetHeaderTypeToUInt64();
        writer->SetFileName(temporary.c_str());
        const int ok = writer->Write();
        const unsigned long code = writer->GetErrorCode();
        if (ok != 1 || code != vtkErrorCode::NoError || errors.failed()) {
            std::string cause =
                code == vtkErrorCode::OutOfDiskSpaceError ? std::string("No space left on device")
                : code != vtkErrorCode::NoError ? vtkErrorCode::GetStringFromErrorCode(code)
                                                : std::string("VTK could not write the file");
            if (errors.failed())
                cause += " (" + errors.message() + ")";
            throw FileError(
                path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: %1"), {cause}});
        }
    });
}

void writeLocalComplexityVtu(const std::string &path, const LocalComplexity &local)
{
    CellIntArray corners{"corners", {}}, lines{"lines", {}}, surfaces{"surfaces", {}},
        regions{"regions", {}}, total{"total", {}};
    for (const CellElementCounts &c : local.counts) {
        corners.values.push_back(c.corners);
        lines.values.push_back(c.lines);
        surfaces.values.push_back(c.surfaces);
        regions.values.push_back(c.regions);
        total.values.push_back(c.total());
    }
    writeCellsVtu(path, local.cvt.cells, {corners, lines, surfaces, regions, total});
}

} // namespace stratamesh
