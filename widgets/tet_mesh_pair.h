// The TetGen comparison meshes of the input (left view) and of its remesh (right view), drawn
// alike: one colouring and one clip plane for both, the plane placed in the bounds of both
// meshes together so that it cuts the same place in the two views.
#pragma once

#include "tet_mesh_scene.h"

#include <memory>

class vtkRenderer;

namespace stratamesh {

enum class ClipAxis { X, Y, Z };

class TetMeshPair {
public:
    TetMeshPair(vtkRenderer *input, vtkRenderer *output);

    // Either may be nullptr (an input-only run, or a side where TetGen failed).
    void setMeshes(std::shared_ptr<const VolumeMesh> input,
                   std::shared_ptr<const VolumeMesh> output);
    void clear() { setMeshes(nullptr, nullptr); }
    bool hasMesh() const { return m_input.mesh() || m_output.mesh(); }

    void setColouring(TetColouring colouring);
    // `fraction` in [0, 1] across the common bounds along `axis`. The kept side faces the default
    // camera (south-west, from above): the tets east of x, north of y, or below z.
    void setClip(bool enabled, ClipAxis axis, double fraction);
    bool isClipped() const { return m_clipEnabled; }
    void setTitles(const char *region, const char *minDihedral);

    TetMeshScene &input() { return m_input; }
    TetMeshScene &output() { return m_output; }
    const TetMeshScene &input() const { return m_input; }
    const TetMeshScene &output() const { return m_output; }

private:
    void applyClip();

    TetMeshScene m_input;
    TetMeshScene m_output;
    bool m_clipEnabled = false;
    ClipAxis m_axis = ClipAxis::Y;
    double m_fraction = 0.5;
};

} // namespace stratamesh
