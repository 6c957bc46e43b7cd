#include "io/vtk_reader.h"

#include "common/error.h"
#include "io/vtk_common.h"

#include <vtkAbstractArray.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace stratamesh {

namespace {

std::string lowerExtension(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string stem(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    return dot == std::string::npos ? base : base.substr(0, dot);
}

// Names written by our writer (bytes, each name ended by '\n'), or a VTK string array.
std::vector<std::string> stringsOf(vtkFieldData *fd, const char *name)
{
    std::vector<std::string> out;
    vtkAbstractArray *array = fd ? fd->GetAbstractArray(name) : nullptr;
    if (auto *a = vtkStringArray::SafeDownCast(array)) {
        for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
            out.push_back(a->GetValue(i));
    } else if (auto *bytes = vtkDataArray::SafeDownCast(array)) {
        std::string current;
        for (vtkIdType i = 0; i < bytes->GetNumberOfValues(); ++i) {
            const char c = static_cast<char>(static_cast<unsigned char>(bytes->GetComponent(i, 0)));
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
    for (FeatureType t : {FeatureType::Horizon, FeatureType::Fault, FeatureType::Unconformity, FeatureType::Boundary})
        if (featureTypeName(t) == word)
            return t;
    return FeatureType::Unknown;
}

template <class Reader>
vtkSmartPointer<vtkDataSet> runReader(const std::string &path)
{
    vtkNew<Reader> reader;
    VtkErrorCapture errors(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    const unsigned long code = reader->GetErrorCode();
    vtkDataSet *out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    if (errors.failed() || code != vtkErrorCode::NoError || !out) {
        const std::string cause = errors.failed() ? errors.message()
                                  : code != vtkErrorCode::NoError ? vtkErrorCode::GetStringFromErrorCode(code)
                                                                  : "not a VTK data set";
        throw FileError(path, 0, "cannot read: " + cause);
    }
    return out;
}

// Integer cell array by name, or null.
vtkDataArray *intArray(vtkDataSet *data, const char *name)
{
    vtkDataArray *a = data->GetCellData()->GetArray(name);
    return a && a->GetNumberOfComponents() == 1 && a->GetNumberOfTuples() == data->GetNumberOfCells() ? a
                                                                                                    : nullptr;
}

int groupValue(vtkDataArray *a, vtkIdType cell, int fallback)
{
    return a ? static_cast<int>(a->GetComponent(cell, 0)) : fallback;
}

// Names for group ids 0..max: from field data, else "<kind>_<id+1>".
std::vector<std::string> groupNames(std::vector<std::string> names, int maxId, const char *kind)
{
    for (int i = static_cast<int>(names.size()); i <= maxId; ++i)
        names.push_back(std::string(kind) + "_" + std::to_string(i + 1));
    return names;
}

} // namespace

VolumeMesh readVtk(const std::string &path)
{
    if (!std::ifstream(path).good())
        throw FileError(path, 0, "cannot open the file");
    const std::string ext = lowerExtension(path);
    vtkSmartPointer<vtkDataSet> data;
    if (ext == ".vtu")
        data = runReader<vtkXMLUnstructuredGridReader>(path);
    else if (ext == ".vtp")
        data = runReader<vtkXMLPolyDataReader>(path);
    else if (ext == ".vtk")
        data = runReader<vtkDataSetReader>(path);
    else
        throw FileError(path, 0, "unknown VTK extension '" + ext + "' (use .vtu, .vtp or .vtk)");

    VolumeMesh mesh;
    vtkFieldData *fd = data->GetFieldData();
    const std::vector<std::string> meshName = stringsOf(fd, vtkarrays::meshName);
    mesh.name = meshName.empty() ? stem(path) : meshName.front();
    if (vtkDataArray *depth = fd ? fd->GetArray(vtkarrays::zPositiveDepth) : nullptr)
        mesh.zPositiveDepth = depth->GetNumberOfTuples() > 0 && depth->GetComponent(0, 0) != 0;
    mesh.points.resize(static_cast<std::size_t>(data->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
        data->GetPoint(i, mesh.points[static_cast<std::size_t>(i)].data());

    vtkDataArray *regionIds = intArray(data, vtkarrays::regionId);
    vtkDataArray *surfaceIds = intArray(data, vtkarrays::surfaceId);
    vtkDataArray *lineIds = intArray(data, vtkarrays::lineId);
    const std::vector<std::string> qualityName = stringsOf(fd, vtkarrays::qualityName);
    vtkDataArray *quality = qualityName.empty() ? nullptr : intArray(data, qualityName.front().c_str());
    int maxRegion = -1, maxSurface = -1, maxLine = -1;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
        const int type = data->GetCellType(c);
        data->GetCellPoints(c, ids);
        auto id = [&](int k) { return static_cast<int>(ids->GetId(k)); };
        switch (type) {
        case VTK_TETRA:
        case VTK_PYRAMID:
        case VTK_WEDGE: {
            Cell cell;
            cell.type = type == VTK_TETRA ? CellType::Tet : type == VTK_PYRAMID ? CellType::Pyramid : CellType::Prism;
            for (int k = 0; k < cell.size(); ++k)
                cell.nodes[k] = id(cell.type == CellType::Prism ? vtkWedgeMap[k] : k);
            mesh.cells.push_back(cell);
            mesh.cellRegion.push_back(groupValue(regionIds, c, 0));
            maxRegion = std::max(maxRegion, mesh.cellRegion.back());
            if (quality)
                mesh.cellQuality.push_back(quality->GetComponent(c, 0));
            break;
        }
        case VTK_TRIANGLE:
            mesh.triangles.push_back({id(0), id(1), id(2)});
            mesh.triangleSurface.push_back(groupValue(surfaceIds, c, 0));
            maxSurface = std::max(maxSurface, mesh.triangleSurface.back());
            break;
        case VTK_LINE:
        case VTK_POLY_LINE:
            for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k) {
                mesh.edges.push_back({id(static_cast<int>(k)), id(static_cast<int>(k + 1))});
                mesh.edgeLine.push_back(groupValue(lineIds, c, 0));
                maxLine = std::max(maxLine, mesh.edgeLine.back());
            }
            break;
        case VTK_VERTEX:
        case VTK_POLY_VERTEX:
            for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
                mesh.corners.push_back(id(static_cast<int>(k)));
            break;
        default:
            throw FileError(path, 0, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
                                         ", which StrataMesh does not exchange (tets, pyramids, wedges, "
                                         "triangles, lines and vertices only)");
        }
    }
    if (quality)
        mesh.qualityName = qualityName.front();
    const std::string fallback = stem(path);
    std::vector<std::string> regions = stringsOf(fd, vtkarrays::regionNames);
    if (!regionIds && regions.empty() && !mesh.cells.empty())
        regions = {fallback};
    mesh.regionNames = groupNames(regions, maxRegion, "region");
    std::vector<std::string> surfaceNames = stringsOf(fd, vtkarrays::surfaceNames);
    if (!surfaceIds && surfaceNames.empty() && !mesh.triangles.empty())
        surfaceNames = {fallback};
    surfaceNames = groupNames(surfaceNames, maxSurface, "surface");
    const std::vector<std::string> features = stringsOf(fd, vtkarrays::surfaceFeatures);
    const std::vector<std::string> types = stringsOf(fd, vtkarrays::surfaceTypes);
    for (std::size_t s = 0; s < surfaceNames.size(); ++s)
        mesh.surfaces.push_back({surfaceNames[s], s < features.size() ? features[s] : surfaceNames[s],
                                 s < types.size() ? featureTypeFromName(types[s]) : FeatureType::Unknown});
    std::vector<std::string> lines = stringsOf(fd, vtkarrays::lineNames);
    if (!lineIds && lines.empty() && !mesh.edges.empty())
        lines = {fallback};
    mesh.lineNames = groupNames(lines, maxLine, "line");
    if (vtkDataArray *sides = fd ? fd->GetArray(vtkarrays::regionSides) : nullptr) {
        vtkIdType i = 0;
        const vtkIdType n = sides->GetNumberOfTuples();
        for (std::size_t r = 0; r < mesh.regionNames.size() && i < n; ++r) {
            const int count = static_cast<int>(sides->GetComponent(i++, 0));
            std::vector<RegionSide> list;
            for (int k = 0; k < count && i < n; ++k) {
                const int v = static_cast<int>(sides->GetComponent(i++, 0));
                list.push_back({std::abs(v) - 1, v > 0});
            }
            mesh.regionBoundaries.push_back(std::move(list));
        }
        if (mesh.regionBoundaries.size() != mesh.regionNames.size())
            throw FileError(path, 0, "the RegionSides field data does not match the regions");
    }
    try {
        validateMesh(mesh);
    } catch (const InputError &e) {
        throw FileError(path, 0, e.what());
    }
    return mesh;
}

} // namespace stratamesh
