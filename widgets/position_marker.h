// A sphere drawn at a point of interest (a simplification of the remeshing ledger), visible
// through the surfaces so that a record inside the model can still be found.
#pragma once

#include "model/model.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;
class vtkSphereSource;

namespace stratamesh {

class PositionMarker {
public:
    explicit PositionMarker(vtkRenderer *renderer);
    ~PositionMarker();
    PositionMarker(const PositionMarker &) = delete;
    PositionMarker &operator=(const PositionMarker &) = delete;

    void show(const Vec3 &position, double radius);
    void hide();
    bool isVisible() const;
    // The views stretch z by `factor`: the sphere is squeezed by as much, so it stays round.
    void setVerticalExaggeration(double factor);
    Vec3 position() const { return m_position; }
    double radius() const { return m_radius; }

private:
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkSphereSource> m_sphere;
    vtkSmartPointer<vtkActor> m_actor; // solid, depth-tested
    vtkSmartPointer<vtkActor> m_halo;  // wireframe copy drawn on top of everything
    Vec3 m_position = Vec3::Zero();
    double m_radius = 0.0;
};

} // namespace stratamesh
