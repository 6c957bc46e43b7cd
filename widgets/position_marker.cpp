#include "position_marker.h"

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace stratamesh {

PositionMarker::PositionMarker(vtkRenderer *renderer)
    : m_renderer(renderer), m_sphere(vtkSmartPointer<vtkSphereSource>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()), m_halo(vtkSmartPointer<vtkActor>::New())
{
    m_sphere->SetThetaResolution(24);
    m_sphere->SetPhiResolution(16);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(m_sphere->GetOutputPort());
    m_actor->SetMapper(mapper);
    m_actor->GetProperty()->SetColor(1.0, 0.1, 0.6);
    m_actor->SetVisibility(false);
    m_actor->PickableOff();
    // The same sphere as a translucent shell that ignores depth (coincident-topology offset
    // pulls it forward), so a record hidden behind a surface still shows where it is.
    vtkNew<vtkPolyDataMapper> haloMapper;
    haloMapper->SetInputConnection(m_sphere->GetOutputPort());
    haloMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(0, -66000);
    m_halo->SetMapper(haloMapper);
    m_halo->GetProperty()->SetColor(1.0, 0.1, 0.6);
    m_halo->GetProperty()->SetOpacity(0.35);
    m_halo->SetVisibility(false);
    m_halo->PickableOff();
    m_renderer->AddActor(m_actor);
    m_renderer->AddActor(m_halo);
}

PositionMarker::~PositionMarker()
{
    m_renderer->RemoveActor(m_actor);
    m_renderer->RemoveActor(m_halo);
}

void PositionMarker::show(const Vec3 &position, double radius)
{
    m_position = position;
    m_radius = radius;
    // Placed by the actors, not the source: their scale then squeezes the sphere about its own
    // centre (setVerticalExaggeration).
    m_sphere->SetCenter(0.0, 0.0, 0.0);
    m_sphere->SetRadius(radius);
    m_actor->SetPosition(position.x(), position.y(), position.z());
    m_halo->SetPosition(position.x(), position.y(), position.z());
    m_actor->SetVisibility(true);
    m_halo->SetVisibility(true);
}

void PositionMarker::hide()
{
    m_actor->SetVisibility(false);
    m_halo->SetVisibility(false);
}

bool PositionMarker::isVisible() const
{
    return m_actor->GetVisibility();
}

void PositionMarker::setVerticalExaggeration(double factor)
{
    if (!(factor > 0.0))
        return;
    m_actor->SetScale(1.0, 1.0, 1.0 / factor);
    m_halo->SetScale(1.0, 1.0, 1.0 / factor);
}

} // namespace stratamesh
