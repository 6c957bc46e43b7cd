// One entity of a model drawn brighter than the rest in a view, for the Model dock's selection:
// surfaces as an opaque overlay of their own triangles pulled in front of them, a line as a thick
// polyline, a corner as a small sphere (PositionMarker). A surface behind another shows through
// it as a translucent halo. It draws what the scene and the core's
// topology hold; nothing is computed here.
#pragma once

#include "model/model.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace stratamesh {

class ModelScene;
class PositionMarker;

class EntityHighlight {
public:
    explicit EntityHighlight(vtkRenderer *renderer);
    ~EntityHighlight();
    EntityHighlight(const EntityHighlight &) = delete;
    EntityHighlight &operator=(const EntityHighlight &) = delete;

    // These surfaces of `scene` (indices of its model), one overlay; hidden surfaces too, so
    // that a surface unchecked in the tree can still be found.
    void showSurfaces(const ModelScene &scene, const std::vector<int> &surfaces);
    void showLine(const Model &model, int line);
    void showCorner(const Model &model, int corner, double radius);
    void hide();

    bool isVisible() const;
    // Triangles of the surface overlay (0 when it is hidden); segments of the line overlay.
    int triangleCount() const;
    int segmentCount() const;
    vtkActor *surfaceOverlay() const { return m_surfaces; }
    vtkActor *lineOverlay() const { return m_line; }
    const PositionMarker &cornerMarker() const { return *m_corner; }

private:
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkActor> m_surfaces;
    vtkSmartPointer<vtkActor> m_halo; // the same triangles, translucent, through what hides them
    vtkSmartPointer<vtkActor> m_line;
    std::unique_ptr<PositionMarker> m_corner;
};

} // namespace stratamesh
