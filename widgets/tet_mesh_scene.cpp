#include "tet_mesh_scene.h"

#include "io/vtk_common.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkExtractGeometry.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVariant.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace stratamesh {

namespace {

constexpr const char *kRegionArray = "region";
constexpr const char *kDihedralArray = "min_dihedral_deg";
constexpr const char *kTypeArray = "cell_type";

// Regions are categories: distinct, mid-saturated hues that stay readable under the lights.
constexpr std::array<std::array<double, 3>, 10> kRegionPalette{{{0.55, 0.71, 0.85},
                                                                {0.96, 0.73, 0.45},
                                                                {0.60, 0.80, 0.55},
                                                                {0.80, 0.62, 0.80},
                                                                {0.90, 0.85, 0.50},
                                                                {0.55, 0.80, 0.78},
                                                                {0.85, 0.65, 0.60},
                                                                {0.70, 0.70, 0.90},
                                                                {0.75, 0.85, 0.45},
                                                                {0.80, 0.75, 0.65}}};

// Cell types in a hue each, far from the region palette's pastels: a prism among tets stands out.
constexpr std::array<std::array<double, 3>, 3> kTypePalette{
    {{0.42, 0.62, 0.88}, {0.95, 0.55, 0.15}, {0.20, 0.70, 0.40}}};

int vtkCellTypeOf(CellType type)
{
    return type == CellType::Tet ? VTK_TETRA : type == CellType::Pyramid ? VTK_PYRAMID : VTK_WEDGE;
}

vtkSmartPointer<vtkUnstructuredGrid> cellGrid(const VolumeMesh &mesh)
{
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble(); // Gocad coordinates (~1e6) lose digits in float
    points->SetNumberOfPoints(vtkIdType(mesh.points.size()));
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        points->SetPoint(vtkIdType(i), mesh.points[i].data());
    vtkNew<vtkCellArray> tets;
    std::vector<int> types;
    vtkNew<vtkIntArray> type;
    type->SetName(kTypeArray);
    vtkNew<vtkIntArray> region;
    region->SetName(kRegionArray);
    vtkNew<vtkDoubleArray> dihedral;
    dihedral->SetName(kDihedralArray);
    const bool hasQuality = mesh.cellQuality.size() == mesh.cells.size();
    const bool hasRegions = mesh.cellRegion.size() == mesh.cells.size();
    const int n = int(mesh.points.size());
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const Cell &cell = mesh.cells[c];
        const int size = cell.size();
        vtkIdType ids[6];
        bool valid = true;
        for (int k = 0; k < size; ++k) {
            // Our prisms turn the other way round their bottom triangle than VTK_WEDGE's.
            const int node = cell.nodes[std::size_t(
                cell.type == CellType::Prism ? vtkWedgeMap[std::size_t(k)] : k)];
            valid = valid && node >= 0 && node < n;
            ids[k] = node;
        }
        if (!valid)
            continue; // never trust indices enough to crash the viewer
        tets->InsertNextCell(size, ids);
        types.push_back(vtkCellTypeOf(cell.type));
        type->InsertNextValue(int(cell.type));
        region->InsertNextValue(hasRegions ? mesh.cellRegion[c] : -1);
        dihedral->InsertNextValue(hasQuality ? mesh.cellQuality[c]
                                             : std::numeric_limits<double>::quiet_NaN());
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->SetCells(types.data(), tets);
    grid->GetCellData()->AddArray(type);
    grid->GetCellData()->AddArray(region);
    grid->GetCellData()->AddArray(dihedral);
    return grid;
}

void styleText(vtkTextProperty *p, int size)
{
    p->SetFontSize(size);
    p->SetColor(0.1, 0.1, 0.1);
    p->ShadowOff();
    p->ItalicOff();
}

} // namespace

TetMeshScene::TetMeshScene(vtkRenderer *renderer)
    : m_renderer(renderer), m_grid(vtkSmartPointer<vtkUnstructuredGrid>::New()),
      m_plane(vtkSmartPointer<vtkPlane>::New()),
      m_extract(vtkSmartPointer<vtkExtractGeometry>::New()),
      m_surface(vtkSmartPointer<vtkDataSetSurfaceFilter>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()),
      m_scalarBar(vtkSmartPointer<vtkScalarBarActor>::New())
{
    // Whole tets crossing the plane are kept: the cut shows the tets themselves, not slices.
    m_extract->SetInputData(m_grid);
    m_extract->SetImplicitFunction(m_plane);
    m_extract->ExtractInsideOn();
    m_extract->ExtractBoundaryCellsOn();
    m_surface->SetInputData(m_grid);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(m_surface->GetOutputPort());
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SetColorModeToMapScalars();
    mapper->ScalarVisibilityOn();
    mapper->UseLookupTableScalarRangeOn();
    m_actor->SetMapper(mapper);
    vtkProperty *p = m_actor->GetProperty();
    p->SetEdgeVisibility(true);
    p->SetEdgeColor(0.18, 0.18, 0.2);
    p->SetLineWidth(0.6f);
    p->SetAmbient(0.25);
    p->SetDiffuse(0.8);
    m_actor->PickableOff();

    m_scalarBar->UnconstrainedFontSizeOn();
    styleText(m_scalarBar->GetTitleTextProperty(), 14);
    styleText(m_scalarBar->GetLabelTextProperty(), 12);
    styleText(m_scalarBar->GetAnnotationTextProperty(), 12);
    m_renderer->AddActor(m_actor);
    m_renderer->AddViewProp(m_scalarBar);
    applyColouring();
    applyVisibility();
}

TetMeshScene::~TetMeshScene()
{
    m_renderer->RemoveActor(m_actor);
    m_renderer->RemoveViewProp(m_scalarBar);
}

void TetMeshScene::setMesh(std::shared_ptr<const VolumeMesh> mesh)
{
    m_mesh = std::move(mesh);
    m_grid = m_mesh ? cellGrid(*m_mesh) : vtkSmartPointer<vtkUnstructuredGrid>::New();
    m_extract->SetInputData(m_grid);
    if (m_clipped)
        m_surface->SetInputConnection(m_extract->GetOutputPort());
    else
        m_surface->SetInputData(m_grid);
    applyColouring();
    applyVisibility();
}

void TetMeshScene::setColouring(TetColouring colouring)
{
    m_colouring = colouring;
    applyColouring();
}

void TetMeshScene::setClipPlane(const double origin[3], const double normal[3])
{
    m_plane->SetOrigin(origin[0], origin[1], origin[2]);
    m_plane->SetNormal(normal[0], normal[1], normal[2]);
    if (!m_clipped)
        m_surface->SetInputConnection(m_extract->GetOutputPort());
    m_clipped = true;
}

void TetMeshScene::clearClipPlane()
{
    if (m_clipped)
        m_surface->SetInputData(m_grid);
    m_clipped = false;
}

void TetMeshScene::setVisible(bool visible)
{
    m_visible = visible;
    applyVisibility();
}

void TetMeshScene::setTitles(const char *region, const char *minDihedral)
{
    m_regionTitle = region;
    m_dihedralTitle = minDihedral;
    applyColouring();
}

void TetMeshScene::setTypeTitles(const char *title, const std::array<std::string, 3> &names)
{
    m_typeTitle = title;
    m_typeNames = names;
    applyColouring();
}

bool TetMeshScene::dihedralRange(double range[2]) const
{
    auto *values = vtkDoubleArray::SafeDownCast(m_grid->GetCellData()->GetArray(kDihedralArray));
    if (!values || values->GetNumberOfTuples() == 0)
        return false;
    values->GetRange(range);
    return !std::isnan(range[0]) && !std::isnan(range[1]);
}

int TetMeshScene::cellCount(CellType type) const
{
    auto *types = vtkIntArray::SafeDownCast(m_grid->GetCellData()->GetArray(kTypeArray));
    if (!types)
        return 0;
    int count = 0;
    for (vtkIdType c = 0; c < types->GetNumberOfTuples(); ++c)
        count += types->GetValue(c) == int(type) ? 1 : 0;
    return count;
}

bool TetMeshScene::bounds(double bounds[6]) const
{
    if (!m_mesh || m_grid->GetNumberOfCells() == 0)
        return false;
    m_grid->GetBounds(bounds);
    return true;
}

int TetMeshScene::tetCount() const
{
    return int(m_grid->GetNumberOfCells());
}

int TetMeshScene::shownTetCount() const
{
    if (!m_clipped)
        return tetCount();
    m_extract->Update();
    return int(m_extract->GetOutput()->GetNumberOfCells());
}

vtkActor *TetMeshScene::actor() const
{
    return m_actor;
}

vtkUnstructuredGrid *TetMeshScene::grid() const
{
    return m_grid;
}

vtkScalarBarActor *TetMeshScene::scalarBar() const
{
    return m_scalarBar;
}

void TetMeshScene::applyColouring()
{
    auto *mapper = vtkPolyDataMapper::SafeDownCast(m_actor->GetMapper());
    if (m_colouring == TetColouring::Region) {
        // One swatch per region, named, in the scalar bar.
        vtkNew<vtkLookupTable> table;
        const int regions = m_mesh ? std::max<int>(1, int(m_mesh->regionNames.size())) : 1;
        table->SetNumberOfTableValues(regions);
        table->IndexedLookupOn();
        for (int r = 0; r < regions; ++r) {
            const auto &c = kRegionPalette[std::size_t(r) % kRegionPalette.size()];
            table->SetTableValue(r, c[0], c[1], c[2], 1.0);
            const std::string name = m_mesh && std::size_t(r) < m_mesh->regionNames.size()
                                         ? m_mesh->regionNames[std::size_t(r)]
                                         : std::to_string(r);
            table->SetAnnotation(vtkVariant(r), name);
        }
        table->SetNanColor(0.6, 0.6, 0.6, 1.0);
        table->Build();
        mapper->SelectColorArray(kRegionArray);
        mapper->SetLookupTable(table);
        m_scalarBar->SetLookupTable(table);
        m_scalarBar->SetTitle(m_regionTitle.c_str());
        m_scalarBar->SetNumberOfLabels(0);
        // Names need width: a column on the left, names right of the swatches (annotations go
        // opposite the labels).
        m_scalarBar->SetOrientationToVertical();
        m_scalarBar->SetTextPositionToPrecedeScalarBar();
        m_scalarBar->SetMaximumWidthInPixels(110);
        m_scalarBar->SetMaximumHeightInPixels(300);
        m_scalarBar->SetPosition(0.02, 0.25);
        m_scalarBar->SetWidth(0.12);
        m_scalarBar->SetHeight(0.5);
    } else if (m_colouring == TetColouring::Type) {
        vtkNew<vtkLookupTable> table;
        table->SetNumberOfTableValues(int(kTypePalette.size()));
        table->IndexedLookupOn();
        for (std::size_t t = 0; t < kTypePalette.size(); ++t) {
            const auto &c = kTypePalette[t];
            table->SetTableValue(vtkIdType(t), c[0], c[1], c[2], 1.0);
            table->SetAnnotation(vtkVariant(int(t)), m_typeNames[t]);
        }
        table->Build();
        mapper->SelectColorArray(kTypeArray);
        mapper->SetLookupTable(table);
        m_scalarBar->SetLookupTable(table);
        m_scalarBar->SetTitle(m_typeTitle.c_str());
        m_scalarBar->SetNumberOfLabels(0);
        // Three short names: a band along the bottom, each name under its swatch, clear of the
        // mesh the camera frames in the middle.
        m_scalarBar->SetOrientationToHorizontal();
        m_scalarBar->SetTextPositionToPrecedeScalarBar();
        m_scalarBar->SetMaximumWidthInPixels(360);
        m_scalarBar->SetMaximumHeightInPixels(90);
        m_scalarBar->SetPosition(0.2, 0.02);
        m_scalarBar->SetWidth(0.6);
        m_scalarBar->SetHeight(0.14);
    } else {
        // Slivers stand out in red; well-shaped tets are calm greens and blues, not alarms.
        vtkNew<vtkColorTransferFunction> colours;
        colours->AddRGBPoint(0.0, 0.80, 0.05, 0.05);
        colours->AddRGBPoint(5.0, 0.95, 0.35, 0.10);
        colours->AddRGBPoint(15.0, 0.98, 0.80, 0.20);
        colours->AddRGBPoint(30.0, 0.50, 0.80, 0.40);
        colours->AddRGBPoint(kDihedralTop, 0.20, 0.45, 0.80);
        colours->SetNanColor(0.6, 0.6, 0.6);
        colours->ClampingOn();
        mapper->SelectColorArray(kDihedralArray);
        mapper->SetLookupTable(colours);
        m_scalarBar->SetLookupTable(colours);
        m_scalarBar->SetTitle(m_dihedralTitle.c_str());
        m_scalarBar->SetNumberOfLabels(8);
        m_scalarBar->SetLabelFormat("%.0f");
        // Short figures: a band along the bottom, below the mesh and right of the axes marker.
        m_scalarBar->SetOrientationToHorizontal();
        m_scalarBar->SetTextPositionToPrecedeScalarBar();
        m_scalarBar->SetMaximumWidthInPixels(420);
        m_scalarBar->SetMaximumHeightInPixels(80);
        m_scalarBar->SetPosition(0.2, 0.02);
        m_scalarBar->SetWidth(0.7);
        m_scalarBar->SetHeight(0.14);
    }
    mapper->Modified();
}

void TetMeshScene::applyVisibility()
{
    const bool shown = m_visible && m_mesh && m_grid->GetNumberOfCells() > 0;
    m_actor->SetVisibility(shown);
    m_scalarBar->SetVisibility(shown);
}

} // namespace stratamesh
