#include "io/vtk_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/group_index.h"
#include "io/vtk_common.h"
#include "io/vtk_legacy_reader.h"
#include "io/vtk_output_capture.h"
#include "io/vtk_xml_counts.h"

#include <vtkAbstractArray.h>
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <type_traits>
#include <utility>

namespace stratamesh {

namespace {

// Names written by our writer (bytes, each name ended by '\n'), or a VTK string array. A value
// that is not a byte (a double array, a damaged file) is refused rather than cast.
std::vector<std::string> stringsOf(const std::string &path, vtkFieldData *fd, const char *name)
{
    std::vector<std::string> out;
    vtkAbstractArray *array = fd ? fd->GetAbstractArray(name) : nullptr;
    if (auto *a = vtkStringArray::SafeDownCast(array)) {
        for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
            out.push_back(a->GetValue(i));
    } else if (auto *bytes = vtkDataArray::SafeDownCast(array)) {
        std::string current;
        const int components = bytes->GetNumberOfComponents();
        for (vtkIdType i = 0; i < bytes->GetNumberOfValues(); ++i) {
            const double v = bytes->GetComponent(i / components, static_cast<int>(i % components));
            if (!(v >= -128 && v <= 255) || v != std::floor(v))
                throw FileError(
                    path, 0,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "the %1 field data holds %2, not a byte of text"),
                                {name, doubleText(v)}});
            const char c =
                static_cast<char>(static_cast<unsigned char>(static_cast<int>(v) & 0xff));
            if (c == '\n') {
                out.push_back(current);
                current.clear();
            } else {
                current += c;
            }
        }
    }
    return out;
}

FeatureType featureTypeFromName(const std::string &word)
{
    for (FeatureType t : {FeatureType::Horizon, FeatureType::Fault, FeatureType::Unconformity,
                          FeatureType::Boundary})
        if (featureTypeName(t) == word)
            return t;
    return FeatureType::Unknown;
}

template <class Reader>
vtkSmartPointer<vtkDataSet> runReader(const std::string &path)
{
    // A warning is a failure too: VTK warns and goes on reading a file it misunderstood.
    VtkOutputCapture console;
    vtkNew<Reader> reader;
    VtkErrorCapture errors(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    const unsigned long code = reader->GetErrorCode();
    vtkDataSet *out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    std::string cause = errors.message();
    for (const std::string &more : {errors.warnings(), console.message()})
        if (!more.empty())
            cause += (cause.empty() ? "" : "; ") + more;
    if (cause.empty() && code != vtkErrorCode::NoError)
        cause = vtkErrorCode::GetStringFromErrorCode(code);
    if (cause.empty() && !out)
        cause = "not a VTK data set";
    if (!cause.empty())
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "VTK cannot read it: %1"), {cause}});
    return out;
}

// A legacy file's data set as the XML readers give theirs, so that both build the mesh alike:
// an unstructured grid (poly data cells come typed and in VTK's order), its numeric cell arrays
// and its field arrays. Every array holds doubles, as GetComponent gives any type.
vtkSmartPointer<vtkDataSet> legacyDataSet(VtkLegacyData data)
{
    static const std::set<std::string> fieldNames{
        vtkarrays::meshName,     vtkarrays::zPositiveDepth,  vtkarrays::regionNames,
        vtkarrays::surfaceNames, vtkarrays::surfaceFeatures, vtkarrays::surfaceTypes,
        vtkarrays::lineNames,    vtkarrays::qualityName,     vtkarrays::regionSides};
    static_assert(std::is_same_v<vtkIdType, long long>, "point ids are copied as they are");
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(data.points.size() / 3));
    std::copy(data.points.begin(), data.points.end(), coordinates->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    grid->SetPoints(points);
    auto ids = [](const std::vector<long long> &values) {
        auto a = vtkSmartPointer<vtkIdTypeArray>::New();
        a->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
        std::copy(values.begin(), values.end(), a->GetPointer(0));
        return a;
    };
    vtkNew<vtkCellArray> cells;
    cells->SetData(ids(data.offsets), ids(data.connectivity));
    vtkNew<vtkUnsignedCharArray> types;
    types->SetNumberOfValues(static_cast<vtkIdType>(data.cellTypes.size()));
    for (std::size_t c = 0; c < data.cellTypes.size(); ++c)
        types->SetValue(static_cast<vtkIdType>(c), static_cast<unsigned char>(data.cellTypes[c]));
    grid->SetCells(types, cells);
    auto array = [](VtkLegacyArray &a) -> vtkSmartPointer<vtkAbstractArray> {
        if (a.text) {
            auto s = vtkSmartPointer<vtkStringArray>::New();
            s->SetName(a.name.c_str());
            s->SetNumberOfComponents(a.components);
            for (std::string &v : a.strings)
                s->InsertNextValue(v);
            return s;
        }
        auto d = vtkSmartPointer<vtkDoubleArray>::New();
        d->SetName(a.name.c_str());
        d->SetNumberOfComponents(a.components);
        d->SetNumberOfTuples(static_cast<vtkIdType>(a.tuples));
        std::copy(a.values.begin(), a.values.end(), d->GetPointer(0));
        return d;
    };
    // Only the arrays the mesh is built from: vtkFieldData::AddArray looks for each name among
    // the arrays already added, which thousands of arrays would pay in their square.
    std::set<std::string> cellNames{vtkarrays::regionId, vtkarrays::surfaceId, vtkarrays::lineId};
    for (VtkLegacyArray &a : data.fieldArrays) {
        if (!fieldNames.count(a.name))
            continue;
        if (a.name == vtkarrays::qualityName) {
            // Any name it holds (string or "\n"-ended bytes) may be the quality's cell array.
            std::string name;
            for (const std::string &s : a.strings)
                cellNames.insert(s);
            for (double v : a.values)
                if (v == '\n')
                    cellNames.insert(std::exchange(name, std::string()));
                else if (v >= -128 && v <= 255)
                    name += static_cast<char>(static_cast<int>(v) & 0xff);
        }
        grid->GetFieldData()->AddArray(array(a));
    }
    // A string array is no cell array to GetArray: leaving it out keeps it absent.
    for (VtkLegacyArray &a : data.cellArrays)
        if (!a.text && cellNames.count(a.name))
            grid->GetCellData()->AddArray(array(a));
    return grid;
}

// Integer cell array by name, or null.
vtkDataArray *intArray(vtkDataSet *data, const char *name)
{
    vtkDataArray *a = data->GetCellData()->GetArray(name);
    return a && a->GetNumberOfComponents() == 1
                   && a->GetNumberOfTuples() == data->GetNumberOfCells()
               ? a
               : nullptr;
}

// The group id of a cell, refused unless it is a whole number from 0 to INT_MAX.
long long groupValue(const std::string &path, vtkDataArray *a, const char *name, vtkIdType cell)
{
    if (!a)
        return 0;
    const double v = a->GetComponent(cell, 0);
    if (!(v >= 0 && v <= std::numeric_limits<int>::max()) || v != std::floor(v))
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP(
                            "stratamesh::Core",
                            "cell %1 has %2 %3 (expected a whole number from 0 to 2147483647)"),
                        {std::to_string(cell), name, doubleText(v)}});
    return static_cast<long long>(v);
}

} // namespace

VolumeMesh readVtk(const std::string &path)
{
    if (!std::ifstream(path).good())
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the file"));
    const std::string ext = fileExtension(path);
    vtkSmartPointer<vtkDataSet> data;
    if (ext == ".vtu" || ext == ".vtp")
        checkVtkXmlCounts(path);
    if (ext == ".vtu")
        data = runReader<vtkXMLUnstructuredGridReader>(path);
    else if (ext == ".vtp")
        data = runReader<vtkXMLPolyDataReader>(path);
    else if (ext == ".vtk") {
        data = legacyDataSet(readVtkLegacy(path));
    } else
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "unknown VTK extension '%1' (use .vtu, .vtp or .vtk)"),
                        {ext}});

    VolumeMesh mesh;
    vtkFieldData *fd = data->GetFieldData();
    const std::vector<std::string> meshName = stringsOf(path, fd, vtkarrays::meshName);
    mesh.name = meshName.empty() ? fileStem(path) : meshName.front();
    if (vtkDataArray *depth = fd ? fd->GetArray(vtkarrays::zPositiveDepth) : nullptr)
        mesh.zPositiveDepth = depth->GetNumberOfTuples() > 0 && depth->GetComponent(0, 0) != 0;
    mesh.points.resize(static_cast<std::size_t>(data->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
        Vec3 &p = mesh.points[static_cast<std::size_t>(i)];
        data->GetPoint(i, p.data());
        if (MessageText problem = pointProblem(p); !problem.pattern.empty())
            throw FileError(
                path, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "point %1 (numbered from 0): %2"),
                            {std::to_string(i)},
                            {std::move(problem)}});
    }

    vtkDataArray *regionIds = intArray(data, vtkarrays::regionId);
    vtkDataArray *surfaceIds = intArray(data, vtkarrays::surfaceId);
    vtkDataArray *lineIds = intArray(data, vtkarrays::lineId);
    const std::vector<std::string> qualityName = stringsOf(path, fd, vtkarrays::qualityName);
    vtkDataArray *quality =
        qualityName.empty() ? nullptr : intArray(data, qualityName.front().c_str());
    // Group ids are file ids here and become dense indices once all are known.
    std::vector<long long> cellRegion, triangleSurface, edgeLine;
    GroupIndex regionIndex, surfaceIndex, lineIndex;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
        const int type = data->GetCellType(c);
        data->GetCellPoints(c, ids);
        const vtkIdType count = ids->GetNumberOfIds();
        if (MessageText problem =
                vtkCellProblem(c, type, ids->GetPointer(0), count, data->GetNumberOfPoints());
            !problem.pattern.empty())
            throw FileError(path, 0, problem);
        auto id = [&](vtkIdType k) { return static_cast<int>(ids->GetId(k)); };
        switch (type) {
        case VTK_TETRA:
        case VTK_PYRAMID:
        case VTK_WEDGE: {
            Cell cell;
            cell.type = type == VTK_TETRA     ? CellType::Tet
                        : type == VTK_PYRAMID ? CellType::Pyramid
                                              : CellType::Prism;
            for (int k = 0; k < cell.size(); ++k)
                cell.nodes[k] = id(cell.type == CellType::Prism ? vtkWedgeMap[k] : k);
            mesh.cells.push_back(cell);
            cellRegion.push_back(groupValue(path, regionIds, vtkarrays::regionId, c));
            regionIndex.add(cellRegion.back());
            if (quality)
                mesh.cellQuality.push_back(quality->GetComponent(c, 0));
            break;
        }
        case VTK_TRIANGLE:
            mesh.triangles.push_back({id(0), id(1), id(2)});
            triangleSurface.push_back(groupValue(path, surfaceIds, vtkarrays::surfaceId, c));
            surfaceIndex.add(triangleSurface.back());
            break;
        case VTK_LINE:
        case VTK_POLY_LINE:
            for (vtkIdType k = 0; k + 1 < count; ++k) {
                mesh.edges.push_back({id(k), id(k + 1)});
                edgeLine.push_back(groupValue(path, lineIds, vtkarrays::lineId, c));
                lineIndex.add(edgeLine.back());
            }
            break;
        case VTK_VERTEX:
        case VTK_POLY_VERTEX:
            for (vtkIdType k = 0; k < count; ++k)
                mesh.corners.push_back(id(k));
            break;
        default:
            break; // refused by vtkCellProblem
        }
    }
    if (mesh.cells.empty() && mesh.triangles.empty())
        throw FileError(
            path, 0,
            QT_TRANSLATE_NOOP("stratamesh::Core",
                              "no triangle and no volume cell in the file (empty model)"));
    if (quality)
        mesh.qualityName = qualityName.front();
    const std::string fallback = fileStem(path);
    std::vector<std::string> regions = stringsOf(path, fd, vtkarrays::regionNames);
    if (!regionIds && regions.empty() && !mesh.cells.empty())
        regions = {fallback};
    regionIndex.number(regions.size());
    mesh.regionNames = regionIndex.names(regions, "region");
    std::vector<std::string> surfaceNames = stringsOf(path, fd, vtkarrays::surfaceNames);
    if (!surfaceIds && surfaceNames.empty() && !mesh.triangles.empty())
        surfaceNames = {fallback};
    surfaceIndex.number(surfaceNames.size());
    surfaceNames = surfaceIndex.names(surfaceNames, "surface");
    const std::vector<std::string> features = stringsOf(path, fd, vtkarrays::surfaceFeatures);
    const std::vector<std::string> types = stringsOf(path, fd, vtkarrays::surfaceTypes);
    for (std::size_t s = 0; s < surfaceNames.size(); ++s)
        mesh.surfaces.push_back(
            {surfaceNames[s], s < features.size() ? features[s] : surfaceNames[s],
             s < types.size() ? featureTypeFromName(types[s]) : FeatureType::Unknown});
    std::vector<std::string> lines = stringsOf(path, fd, vtkarrays::lineNames);
    if (!lineIds && lines.empty() && !mesh.edges.empty())
        lines = {fallback};
    lineIndex.number(lines.size());
    mesh.lineNames = lineIndex.names(lines, "line");
    for (long long v : cellRegion)
        mesh.cellRegion.push_back(regionIndex.indexOf(v));
    for (long long v : triangleSurface)
        mesh.triangleSurface.push_back(surfaceIndex.indexOf(v));
    for (long long v : edgeLine)
        mesh.edgeLine.push_back(lineIndex.indexOf(v));
    if (vtkDataArray *sides = fd ? fd->GetArray(vtkarrays::regionSides) : nullptr) {
        vtkIdType i = 0;
        const vtkIdType n = sides->GetNumberOfTuples();
        for (std::size_t r = 0; r < mesh.regionNames.size() && i < n; ++r) {
            const double count = sides->GetComponent(i++, 0);
            std::vector<RegionSide> list;
            for (int k = 0; k < count && i < n; ++k) {
                const double v = sides->GetComponent(i++, 0);
                const int s = std::abs(v) <= std::numeric_limits<int>::max()
                                  ? surfaceIndex.indexOf(static_cast<long long>(std::abs(v)) - 1)
                                  : -1;
                if (s < 0 || v != std::floor(v))
                    throw FileError(
                        path, 0,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                      "the RegionSides field data names surface "
                                                      "%1, which the file does not have"),
                                    {doubleText(v)}});
                list.push_back({s, v > 0});
            }
            mesh.regionBoundaries.push_back(std::move(list));
        }
        if (mesh.regionBoundaries.size() != mesh.regionNames.size())
            throw FileError(
                path, 0,
                QT_TRANSLATE_NOOP("stratamesh::Core",
                                  "the RegionSides field data does not match the regions"));
    }
    try {
        validateMesh(mesh);
    } catch (const InputError &e) {
        throw FileError(path, 0, causeOf(e));
    }
    return mesh;
}

} // namespace stratamesh
