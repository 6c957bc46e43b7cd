#include "tet_mesh_pair.h"

#include <algorithm>

namespace stratamesh {

TetMeshPair::TetMeshPair(vtkRenderer *input, vtkRenderer *output) : m_input(input), m_output(output)
{
}

void TetMeshPair::setMeshes(std::shared_ptr<const VolumeMesh> input,
                            std::shared_ptr<const VolumeMesh> output)
{
    m_input.setMesh(std::move(input));
    m_output.setMesh(std::move(output));
    applyClip();
}

void TetMeshPair::setColouring(TetColouring colouring)
{
    m_input.setColouring(colouring);
    m_output.setColouring(colouring);
}

void TetMeshPair::setClip(bool enabled, ClipAxis axis, double fraction)
{
    m_clipEnabled = enabled;
    m_axis = axis;
    m_fraction = std::clamp(fraction, 0.0, 1.0);
    applyClip();
}

void TetMeshPair::setTitles(const char *region, const char *minDihedral)
{
    m_input.setTitles(region, minDihedral);
    m_output.setTitles(region, minDihedral);
}

void TetMeshPair::applyClip()
{
    double bounds[6], other[6];
    bool any = m_input.bounds(bounds);
    if (m_output.bounds(other)) {
        for (int k = 0; k < 3 && any; ++k) {
            bounds[2 * k] = std::min(bounds[2 * k], other[2 * k]);
            bounds[2 * k + 1] = std::max(bounds[2 * k + 1], other[2 * k + 1]);
        }
        if (!any)
            std::copy(other, other + 6, bounds);
        any = true;
    }
    if (!m_clipEnabled || !any) {
        m_input.clearClipPlane();
        m_output.clearClipPlane();
        return;
    }
    const int k = int(m_axis);
    double origin[3] = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                        0.5 * (bounds[4] + bounds[5])};
    origin[k] = bounds[2 * k] + m_fraction * (bounds[2 * k + 1] - bounds[2 * k]);
    // The scene keeps the tets on the side the normal points away from.
    double normal[3] = {0.0, 0.0, 0.0};
    normal[k] = m_axis == ClipAxis::Z ? 1.0 : -1.0;
    m_input.setClipPlane(origin, normal);
    m_output.setClipPlane(origin, normal);
}

} // namespace stratamesh
