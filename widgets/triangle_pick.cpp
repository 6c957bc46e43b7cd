#include "triangle_pick.h"

#include "model_scene.h"

#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

namespace stratamesh {

namespace {

// The scene skips triangles with an index out of range; its cell ids count only the others.
int triangleOfCell(const Surface &surface, vtkIdType cell)
{
    const int n = int(surface.vertices.size());
    vtkIdType kept = 0;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
        const Triangle &tri = surface.triangles[t];
        if (tri[0] < 0 || tri[1] < 0 || tri[2] < 0 || tri[0] >= n || tri[1] >= n || tri[2] >= n)
            continue;
        if (kept++ == cell)
            return int(t);
    }
    return -1;
}

} // namespace

std::optional<TrianglePick> pickTriangle(const ModelScene &scene, vtkRenderer *renderer, double x,
                                         double y)
{
    if (!scene.model() || !renderer)
        return std::nullopt;
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.0005);
    picker->PickFromListOn();
    for (int s = 0; s < scene.surfaceActorCount(); ++s)
        if (vtkActor *actor = scene.surfaceActor(s); actor && actor->GetVisibility())
            picker->AddPickList(actor);
    if (!picker->Pick(x, y, 0.0, renderer))
        return std::nullopt;
    const int surface = scene.surfaceOfActor(picker->GetActor());
    if (surface < 0 || picker->GetCellId() < 0)
        return std::nullopt;
    TrianglePick pick;
    pick.surface = surface;
    pick.triangle =
        triangleOfCell(scene.model()->surfaces[std::size_t(surface)], picker->GetCellId());
    if (pick.triangle < 0)
        return std::nullopt;
    // The picker answers in world coordinates: back through the actor's matrix (the views'
    // vertical exaggeration) to the model's.
    double world[4] = {0.0, 0.0, 0.0, 1.0}, p[4];
    picker->GetPickPosition(world);
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(picker->GetActor()->GetMatrix(), inverse);
    inverse->MultiplyPoint(world, p);
    pick.position = Vec3(p[0], p[1], p[2]) / p[3];
    return pick;
}

} // namespace stratamesh
