// Which surface triangle of a scene lies under a point of its view (pick and inspect).
#pragma once

#include "model/model.h"

#include <optional>

class vtkRenderer;

namespace stratamesh {

class ModelScene;

struct TrianglePick {
    int surface = -1;             // index in the scene's model
    int triangle = -1;            // index in Surface::triangles
    Vec3 position = Vec3::Zero(); // where the ray met it
};

// The nearest visible surface triangle of `scene` under display position (x, y) of `renderer`
// (VTK display pixels: origin bottom left); nothing when the ray meets no surface.
std::optional<TrianglePick> pickTriangle(const ModelScene &scene, vtkRenderer *renderer, double x,
                                         double y);

} // namespace stratamesh
