// ModelScene's drawing of what the View menu chooses: colouring by a measure with its scalar bar,
// the clip plane and the highlighted triangles. Kept apart from the entity drawing so that each
// reads on its own; the values all come from the core.
#include "model_scene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace stratamesh {

namespace {

const char *const kMeasureArray = "measure";

void styleText(vtkTextProperty *text, int size)
{
    text->SetFontSize(size);
    text->SetColor(0.1, 0.1, 0.12);
    text->ShadowOff();
    text->BoldOff();
    text->ItalicOff();
}

// Routes the actor's mapper through `clip` while clipped, back to its own data when not. A filter
// rather than a mapper's clipping plane: what remains can be counted, and it is the same cut in
// every renderer.
void routeThroughClip(vtkActor *actor, vtkSmartPointer<vtkClipPolyData> &clip, vtkPlane *plane,
                      bool clipped)
{
    if (!actor)
        return;
    auto *mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (clipped) {
        if (!clip) {
            clip = vtkSmartPointer<vtkClipPolyData>::New();
            clip->SetInputData(vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)));
            clip->InsideOutOn(); // keeps the negative side, as TetMeshScene
            mapper->SetInputConnection(clip->GetOutputPort());
        }
        clip->SetClipFunction(plane);
        clip->Modified();
    } else if (clip) {
        mapper->SetInputData(vtkPolyData::SafeDownCast(clip->GetInput()));
        clip = nullptr;
    }
}

} // namespace

vtkPolyData *ModelScene::surfaceData(std::size_t surface) const
{
    if (surface < m_clips.size() && m_clips[surface])
        return vtkPolyData::SafeDownCast(m_clips[surface]->GetInput());
    return vtkPolyData::SafeDownCast(
        m_surfaceActors[surface]->GetMapper()->GetInputDataObject(0, 0));
}

void ModelScene::setScalarColouring(const std::vector<std::vector<double>> &values, bool perVertex,
                                    vtkLookupTable *table, const std::string &title)
{
    clearScalarColouring();
    if (!table || values.size() != m_surfaceActors.size())
        return;
    m_scalarTable = table;
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i) {
        vtkPolyData *data = surfaceData(i);
        const auto expected = perVertex ? data->GetNumberOfPoints() : data->GetNumberOfCells();
        if (vtkIdType(values[i].size()) != expected)
            continue; // triangles with bad indices were not drawn: the values would shift
        vtkNew<vtkDoubleArray> array;
        array->SetName(kMeasureArray);
        array->SetNumberOfValues(expected);
        for (vtkIdType k = 0; k < expected; ++k)
            array->SetValue(k, values[i][std::size_t(k)]);
        if (perVertex)
            data->GetPointData()->SetScalars(array);
        else
            data->GetCellData()->SetScalars(array);
        auto *mapper = vtkPolyDataMapper::SafeDownCast(m_surfaceActors[i]->GetMapper());
        mapper->SetLookupTable(table);
        mapper->UseLookupTableScalarRangeOn();
        mapper->SetColorModeToMapScalars();
        if (perVertex)
            mapper->SetScalarModeToUsePointData();
        else
            mapper->SetScalarModeToUseCellData();
        mapper->ScalarVisibilityOn();
        data->Modified();
    }
    if (!m_scalarBar) {
        m_scalarBar = vtkSmartPointer<vtkScalarBarActor>::New();
        m_scalarBar->UnconstrainedFontSizeOn();
        styleText(m_scalarBar->GetTitleTextProperty(), 14);
        styleText(m_scalarBar->GetLabelTextProperty(), 12);
        m_scalarBar->SetOrientationToVertical();
        m_scalarBar->SetNumberOfLabels(5);
        m_scalarBar->SetMaximumWidthInPixels(90);
        m_scalarBar->SetMaximumHeightInPixels(300);
        // Right-hand side: the left one belongs to the complexity heat map and the tets.
        m_scalarBar->SetPosition(0.84, 0.25);
        // Labels stay readable over dark colourings of the surfaces behind them.
        m_scalarBar->DrawBackgroundOn();
        m_scalarBar->GetBackgroundProperty()->SetColor(1.0, 1.0, 1.0);
        m_scalarBar->GetBackgroundProperty()->SetOpacity(0.7);
        m_scalarBar->SetWidth(0.12);
        m_scalarBar->SetHeight(0.5);
        m_renderer->AddViewProp(m_scalarBar);
    }
    m_scalarBar->SetLookupTable(table);
    m_scalarBar->SetTitle(title.c_str());
    applyExtrasVisibility();
}

void ModelScene::clearScalarColouring()
{
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i) {
        vtkPolyData *data = surfaceData(i);
        data->GetPointData()->RemoveArray(kMeasureArray);
        data->GetCellData()->RemoveArray(kMeasureArray);
        data->Modified();
        m_surfaceActors[i]->GetMapper()->ScalarVisibilityOff();
    }
    m_scalarTable = nullptr;
    applyExtrasVisibility();
}

vtkScalarBarActor *ModelScene::scalarBar() const
{
    return m_scalarBar;
}

vtkLookupTable *ModelScene::lookupTable() const
{
    return m_scalarTable;
}

bool ModelScene::hasScalarColouring() const
{
    return m_scalarTable != nullptr;
}

vtkDataArray *ModelScene::surfaceScalars(int surface) const
{
    if (!m_scalarTable || surface < 0 || std::size_t(surface) >= m_surfaceActors.size())
        return nullptr;
    vtkPolyData *data = surfaceData(std::size_t(surface));
    if (auto *cells = data->GetCellData()->GetArray(kMeasureArray))
        return cells;
    return data->GetPointData()->GetArray(kMeasureArray);
}

void ModelScene::setClipPlane(const double origin[3], const double normal[3])
{
    if (!m_plane)
        m_plane = vtkSmartPointer<vtkPlane>::New();
    m_plane->SetOrigin(origin);
    m_plane->SetNormal(normal);
    m_clipped = true;
    applyClip();
}

void ModelScene::clearClipPlane()
{
    m_clipped = false;
    applyClip();
}

void ModelScene::applyClip()
{
    m_clips.resize(m_surfaceActors.size());
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i)
        routeThroughClip(m_surfaceActors[i], m_clips[i], m_plane, m_clipped);
    vtkActor *others[6] = {m_lines,      m_boxLines,  m_corners,
                           m_boxCorners, m_highlight, m_boxHighlight};
    for (std::size_t k = 0; k < m_otherClips.size(); ++k)
        routeThroughClip(others[k], m_otherClips[k], m_plane, m_clipped);
}

int ModelScene::shownTriangleCount() const
{
    int n = 0;
    for (std::size_t i = 0; i < m_surfaceActors.size(); ++i) {
        if (!m_surfaceActors[i]->GetVisibility())
            continue;
        if (i < m_clips.size() && m_clips[i]) {
            m_clips[i]->Update();
            n += int(m_clips[i]->GetOutput()->GetNumberOfPolys());
        } else {
            n += int(surfaceData(i)->GetNumberOfPolys());
        }
    }
    return n;
}

void ModelScene::setHighlight(const std::vector<std::pair<int, int>> &triangles)
{
    for (auto *actor : {&m_highlight, &m_boxHighlight}) {
        if (*actor)
            m_renderer->RemoveActor(*actor);
        *actor = nullptr;
    }
    m_otherClips[4] = m_otherClips[5] = nullptr;
    m_highlightCount = 0;
    if (!m_model || triangles.empty())
        return;
    vtkNew<vtkPoints> points[2];
    vtkNew<vtkCellArray> cells[2]; // [1]: box triangles
    for (auto &p : points)
        p->SetDataTypeToDouble();
    for (const auto &[s, t] : triangles) {
        if (s < 0 || std::size_t(s) >= m_model->surfaces.size())
            continue;
        const Surface &surface = m_model->surfaces[std::size_t(s)];
        if (t < 0 || std::size_t(t) >= surface.triangles.size())
            continue;
        const Triangle &tri = surface.triangles[std::size_t(t)];
        if (std::any_of(tri.begin(), tri.end(),
                        [&](int v) { return v < 0 || std::size_t(v) >= surface.vertices.size(); }))
            continue;
        const int side = surface.type == FeatureType::Boundary ? 1 : 0;
        vtkIdType ids[3];
        for (int k = 0; k < 3; ++k)
            ids[k] = points[side]->InsertNextPoint(surface.vertices[std::size_t(tri[k])].data());
        cells[side]->InsertNextCell(3, ids);
        ++m_highlightCount;
    }
    for (int side = 0; side < 2; ++side) {
        if (cells[side]->GetNumberOfCells() == 0)
            continue;
        vtkNew<vtkPolyData> data;
        data->SetPoints(points[side]);
        data->SetPolys(cells[side]);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(data);
        mapper->ScalarVisibilityOff();
        // Drawn over the surfaces it lies on, which are pushed back by the global polygon offset.
        mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-4.0, -4.0);
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        vtkProperty *p = actor->GetProperty();
        p->SetColor(1.0, 0.1, 0.75); // magenta: in no colour map and no feature palette
        p->SetAmbient(0.4);
        p->EdgeVisibilityOn();
        p->SetEdgeColor(0.35, 0.0, 0.25);
        p->SetLineWidth(1.5f);
        actor->PickableOff();
        m_renderer->AddActor(actor);
        (side == 0 ? m_highlight : m_boxHighlight) = actor;
    }
    applyClip();
    applyExtrasVisibility();
}

void ModelScene::applyExtrasVisibility()
{
    if (m_scalarBar)
        m_scalarBar->SetVisibility(m_visible && m_scalarTable != nullptr);
    if (m_highlight)
        m_highlight->SetVisibility(m_visible);
    if (m_boxHighlight)
        m_boxHighlight->SetVisibility(m_visible && m_boxVisible);
}

void ModelScene::clearExtras()
{
    if (m_scalarBar)
        m_renderer->RemoveViewProp(m_scalarBar);
    m_scalarBar = nullptr;
    m_scalarTable = nullptr;
    for (auto *actor : {&m_highlight, &m_boxHighlight}) {
        if (*actor)
            m_renderer->RemoveActor(*actor);
        *actor = nullptr;
    }
    m_highlightCount = 0;
    // The actors they fed are gone; the plane itself is kept.
    m_clips.clear();
    for (auto &clip : m_otherClips)
        clip = nullptr;
}

} // namespace stratamesh
