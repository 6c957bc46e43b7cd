#include "io/vtk_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/vtk_common.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <limits>

namespace stratamesh {

namespace {

int vtkTypeOf(CellType type)
{
    return type == CellType::Tet ? VTK_TETRA : type == CellType::Pyramid ? VTK_PYRAMID : VTK_WEDGE;
}

// Names as UTF-8 bytes, each ended by '\n', in an unsigned char array: VTK string arrays would
// be more natural but common readers (meshio) reject them.
vtkSmartPointer<vtkUnsignedCharArray> strings(const char *name,
                                              const std::vector<std::string> &values)
{
    auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
    a->SetName(name);
    for (const std::string &v : values) {
        for (char c : v)
            a->InsertNextValue(static_cast<unsigned char>(c == '\n' || c == '\r' ? ' ' : c));
        a->InsertNextValue('\n');
    }
    return a;
}

// An empty list is left out: meshio 1.x cannot read an empty binary array (its whole read
// fails) and our reader takes a missing list as empty.
void addStrings(vtkFieldData *fd, const char *name, const std::vector<std::string> &values)
{
    if (!values.empty())
        fd->AddArray(strings(name, values));
}

vtkSmartPointer<vtkIntArray> ints(const char *name)
{
    auto a = vtkSmartPointer<vtkIntArray>::New();
    a->SetName(name);
    return a;
}

void addFieldData(vtkFieldData *fd, const VolumeMesh &mesh)
{
    fd->AddArray(strings(vtkarrays::meshName, {mesh.name}));
    auto depth = ints(vtkarrays::zPositiveDepth);
    depth->InsertNextValue(mesh.zPositiveDepth ? 1 : 0);
    fd->AddArray(depth);
    addStrings(fd, vtkarrays::regionNames, mesh.regionNames);
    std::vector<std::string> names, features, types;
    for (const MeshSurface &s : mesh.surfaces) {
        names.push_back(s.name);
        features.push_back(s.featureName);
        types.push_back(featureTypeName(s.type));
    }
    addStrings(fd, vtkarrays::surfaceNames, names);
    addStrings(fd, vtkarrays::surfaceFeatures, features);
    addStrings(fd, vtkarrays::surfaceTypes, types);
    addStrings(fd, vtkarrays::lineNames, mesh.lineNames);
    if (!mesh.cellQuality.empty())
        fd->AddArray(strings(vtkarrays::qualityName, {mesh.qualityName}));
    if (!mesh.regionBoundaries.empty()) {
        auto sides = ints(vtkarrays::regionSides);
        for (const auto &list : mesh.regionBoundaries) {
            sides->InsertNextValue(static_cast<int>(list.size()));
            for (const RegionSide &s : list)
                sides->InsertNextValue(s.positive ? s.surface + 1 : -(s.surface + 1));
        }
        fd->AddArray(sides);
    }
}

// Per-element cell data, filled in the order elements are inserted.
struct CellArrays {
    vtkNew<vtkIntArray> region, surface, line;
    vtkNew<vtkUnsignedCharArray> type;
    vtkNew<vtkDoubleArray> quality;
    bool withQuality = false;

    explicit CellArrays(const VolumeMesh &mesh)
    {
        region->SetName(vtkarrays::regionId);
        surface->SetName(vtkarrays::surfaceId);
        line->SetName(vtkarrays::lineId);
        type->SetName(vtkarrays::cellType);
        withQuality = !mesh.cellQuality.empty();
        quality->SetName(mesh.qualityName.empty() ? "quality" : mesh.qualityName.c_str());
    }
    void add(int vtkType, int r, int s, int l, double q)
    {
        region->InsertNextValue(r);
        surface->InsertNextValue(s);
        line->InsertNextValue(l);
        type->InsertNextValue(static_cast<unsigned char>(vtkType));
        if (withQuality)
            quality->InsertNextValue(q);
    }
    void attach(vtkCellData *cd)
    {
        cd->AddArray(region);
        cd->AddArray(surface);
        cd->AddArray(line);
        cd->AddArray(type);
        if (withQuality)
            cd->AddArray(quality);
    }
};

vtkSmartPointer<vtkPoints> makePoints(const VolumeMesh &mesh)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points
        ->SetDataTypeToDouble(); // float would lose digits of real coordinates (formats.md fact 9)
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].data());
    return points;
}

vtkSmartPointer<vtkUnstructuredGrid> makeGrid(const VolumeMesh &mesh)
{
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(makePoints(mesh));
    grid->Allocate(static_cast<vtkIdType>(mesh.cells.size() + mesh.triangles.size()
                                          + mesh.edges.size() + mesh.corners.size()));
    CellArrays arrays(mesh);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const Cell &cell = mesh.cells[c];
        vtkIdType ids[6];
        for (int k = 0; k < cell.size(); ++k)
            ids[k] = cell.nodes[cell.type == CellType::Prism ? vtkWedgeMap[k] : k];
        const int type = vtkTypeOf(cell.type);
        grid->InsertNextCell(type, cell.size(), ids);
        arrays.add(type, mesh.cellRegion[c], -1, -1,
                   arrays.withQuality ? mesh.cellQuality[c] : nan);
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const vtkIdType ids[3] = {mesh.triangles[t][0], mesh.triangles[t][1], mesh.triangles[t][2]};
        grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
        arrays.add(VTK_TRIANGLE, -1, mesh.triangleSurface[t], -1, nan);
    }
    for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
        const vtkIdType ids[2] = {mesh.edges[e][0], mesh.edges[e][1]};
        grid->InsertNextCell(VTK_LINE, 2, ids);
        arrays.add(VTK_LINE, -1, -1, mesh.edgeLine[e], nan);
    }
    for (int corner : mesh.corners) {
        const vtkIdType id = corner;
        grid->InsertNextCell(VTK_VERTEX, 1, &id);
        arrays.add(VTK_VERTEX, -1, -1, -1, nan);
    }
    arrays.attach(grid->GetCellData());
    addFieldData(grid->GetFieldData(), mesh);
    return grid;
}

vtkSmartPointer<vtkPolyData> makePolyData(const VolumeMesh &mesh)
{
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(makePoints(mesh));
    vtkNew<vtkCellArray> verts, lines, polys;
    CellArrays arrays(mesh);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Poly data numbers its cells vertices first, then lines, then polygons.
    for (int corner : mesh.corners) {
        const vtkIdType id = corner;
        verts->InsertNextCell(1, &id);
        arrays.add(VTK_VERTEX, -1, -1, -1, nan);
    }
    for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
        const vtkIdType ids[2] = {mesh.edges[e][0], mesh.edges[e][1]};
        lines->InsertNextCell(2, ids);
        arrays.add(VTK_LINE, -1, -1, mesh.edgeLine[e], nan);
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const vtkIdType ids[3] = {mesh.triangles[t][0], mesh.triangles[t][1], mesh.triangles[t][2]};
        polys->InsertNextCell(3, ids);
        arrays.add(VTK_TRIANGLE, -1, mesh.triangleSurface[t], -1, nan);
    }
    poly->SetVerts(verts);
    poly->SetLines(lines);
    poly->SetPolys(polys);
    arrays.attach(poly->GetCellData());
    addFieldData(poly->GetFieldData(), mesh);
    return poly;
}

template <class Writer>
void runWriter(Writer *writer, const std::string &target, const std::string &temporary)
{
    VtkErrorCapture errors(writer);
    writer->SetFileName(temporary.c_str());
    const int ok = writer->Write();
    const unsigned long code = writer->GetErrorCode();
    if (ok != 1 || code != vtkErrorCode::NoError || errors.failed()) {
        std::string cause =
            code == vtkErrorCode::OutOfDiskSpaceError ? std::string("No space left on device")
            : code != vtkErrorCode::NoError           ? vtkErrorCode::GetStringFromErrorCode(code)
                                                      : std::string("VTK could not write the file");
        if (errors.failed())
            cause += " (" + errors.message() + ")";
        throw FileError(
            target, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "cannot write: %1"), {cause}});
    }
}

} // namespace

void writeVtk(const VolumeMesh &mesh, const std::string &path, VtkFileKind kind)
{
    validateMesh(mesh);
    if (kind == VtkFileKind::Vtp && mesh.hasCells())
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "a .vtp file holds surfaces only: the mesh '%1' "
                                                  "has %2 volume cells (use .vtu or .vtk)"),
            {mesh.name, std::to_string(mesh.cells.size())}});
    writeFileAtomically(path, [&](const std::string &temporary) {
        if (kind == VtkFileKind::Vtp) {
            vtkNew<vtkXMLPolyDataWriter> writer;
            writer->SetInputData(makePolyData(mesh));
            writer->SetDataModeToBinary();
            writer->SetHeaderTypeToUInt64();
            runWriter(writer.GetPointer(), path, temporary);
        } else if (kind == VtkFileKind::Vtu) {
            vtkNew<vtkXMLUnstructuredGridWriter> writer;
            writer->SetInputData(makeGrid(mesh));
            writer->SetDataModeToBinary();
            writer->SetHeaderTypeToUInt64();
            runWriter(writer.GetPointer(), path, temporary);
        } else {
            vtkNew<vtkUnstructuredGridWriter> writer;
            writer->SetInputData(makeGrid(mesh));
            writer->SetFileVersion(
                42); // classic CELLS layout that older readers know (formats.md fact 9)
            writer->SetFileTypeToBinary(); // ASCII legacy output rounds doubles
            runWriter(writer.GetPointer(), path, temporary);
        }
    });
}

} // namespace stratamesh
