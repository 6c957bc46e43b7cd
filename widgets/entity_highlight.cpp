#include "entity_highlight.h"

#include "model_scene.h"
#include "position_marker.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace stratamesh {

namespace {

// Bright yellow: no feature colour of the palette is near it.
constexpr double kHighlight[3] = {1.0, 0.78, 0.0};

vtkSmartPointer<vtkActor> overlayActor()
{
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->ScalarVisibilityOff();
    // In front of the surface it copies (same triangles): a larger pull than the scene's offset.
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2, -4);
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2, -8);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kHighlight[0], kHighlight[1], kHighlight[2]);
    actor->GetProperty()->SetAmbient(0.35);
    actor->SetVisibility(false);
    actor->PickableOff(); // a click picks the model's own triangles
    return actor;
}

vtkPolyData *overlayData(vtkActor *actor)
{
    return vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
}

} // namespace

EntityHighlight::EntityHighlight(vtkRenderer *renderer)
    : m_renderer(renderer), m_surfaces(overlayActor()), m_halo(overlayActor()),
      m_line(overlayActor()), m_corner(std::make_unique<PositionMarker>(renderer))
{
    vtkProperty *s = m_surfaces->GetProperty();
    s->EdgeVisibilityOn(); // the triangles stay readable under the flat colour
    s->SetEdgeColor(0.55, 0.4, 0.0);
    // As PositionMarker's halo: an offset so large that depth no longer hides it.
    m_halo->GetMapper()->SetRelativeCoincidentTopologyPolygonOffsetParameters(0, -66000);
    m_halo->GetProperty()->SetOpacity(0.35);
    m_halo->GetProperty()->LightingOff();
    vtkProperty *l = m_line->GetProperty();
    l->SetLineWidth(8.0f);
    l->RenderLinesAsTubesOn();
    m_renderer->AddActor(m_surfaces);
    m_renderer->AddActor(m_halo);
    m_renderer->AddActor(m_line);
}

EntityHighlight::~EntityHighlight()
{
    m_renderer->RemoveActor(m_surfaces);
    m_renderer->RemoveActor(m_halo);
    m_renderer->RemoveActor(m_line);
}

void EntityHighlight::showSurfaces(const ModelScene &scene, const std::vector<int> &surfaces)
{
    hide();
    vtkNew<vtkAppendPolyData> append;
    int inputs = 0;
    for (int s : surfaces)
        if (vtkActor *actor = scene.surfaceActor(s))
            if (vtkPolyData *data = overlayData(actor)) {
                append->AddInputData(data);
                ++inputs;
            }
    if (inputs == 0)
        return;
    append->Update();
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->ShallowCopy(append->GetOutput());
    vtkPolyDataMapper::SafeDownCast(m_surfaces->GetMapper())->SetInputData(data);
    vtkPolyDataMapper::SafeDownCast(m_halo->GetMapper())->SetInputData(data);
    m_surfaces->SetVisibility(true);
    m_halo->SetVisibility(true);
}

void EntityHighlight::showLine(const Model &model, int line)
{
    hide();
    if (line < 0 || std::size_t(line) >= model.lines.size())
        return;
    const Line &l = model.lines[std::size_t(line)];
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int v : l.vertices)
        if (v >= 0 && std::size_t(v) < model.vertices.size())
            points->InsertNextPoint(model.vertices[std::size_t(v)].data());
    if (l.closed && points->GetNumberOfPoints() > 2)
        points->InsertNextPoint(points->GetPoint(0));
    if (points->GetNumberOfPoints() < 2)
        return;
    vtkNew<vtkIdList> ids;
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        ids->InsertNextId(i);
    vtkNew<vtkCellArray> cells;
    cells->InsertNextCell(ids);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetLines(cells);
    vtkPolyDataMapper::SafeDownCast(m_line->GetMapper())->SetInputData(data);
    m_line->SetVisibility(true);
}

void EntityHighlight::showCorner(const Model &model, int corner, double radius)
{
    hide();
    if (corner < 0 || std::size_t(corner) >= model.corners.size())
        return;
    const int v = model.corners[std::size_t(corner)].vertex;
    if (v >= 0 && std::size_t(v) < model.vertices.size())
        m_corner->show(model.vertices[std::size_t(v)], radius);
}

void EntityHighlight::hide()
{
    m_surfaces->SetVisibility(false);
    m_halo->SetVisibility(false);
    m_line->SetVisibility(false);
    m_corner->hide();
}

bool EntityHighlight::isVisible() const
{
    return m_surfaces->GetVisibility() || m_line->GetVisibility() || m_corner->isVisible();
}

int EntityHighlight::triangleCount() const
{
    vtkPolyData *data = overlayData(m_surfaces);
    return m_surfaces->GetVisibility() && data ? int(data->GetNumberOfPolys()) : 0;
}

int EntityHighlight::segmentCount() const
{
    vtkPolyData *data = overlayData(m_line);
    return m_line->GetVisibility() && data ? int(data->GetNumberOfPoints()) - 1 : 0;
}

} // namespace stratamesh
