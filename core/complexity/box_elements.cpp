#include "complexity/box_elements.h"

#include "common/error.h"
#include "model/model_counts.h"

namespace stratamesh {

namespace {
std::vector<int> indicesOf(const std::vector<bool> &isBox)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < isBox.size(); ++i)
        if (!isBox[i])
            out.push_back(static_cast<int>(i));
    return out;
}
} // namespace

std::vector<int> BoxElements::innerSurfaces() const
{
    return indicesOf(surface);
}
std::vector<int> BoxElements::innerLines() const
{
    return indicesOf(line);
}
std::vector<int> BoxElements::innerCorners() const
{
    return indicesOf(corner);
}

BoxElements boxElements(const Model &model)
{
    if (!model.hasTopology())
        throw InputError(
            "complexity: the model has no topology (lines and corners); recover it first");
    BoxElements box;
    box.surface.resize(model.surfaces.size());
    std::vector<bool> boxVertex(model.vertices.size(), false);
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        box.surface[s] = isBoxSurface(model.surfaces[s]);
        if (box.surface[s])
            for (int v : model.surfaceVertexToGlobal[s])
                boxVertex[v] = true;
    }
    box.line.resize(model.lines.size());
    for (std::size_t l = 0; l < model.lines.size(); ++l)
        for (int s : model.lines[l].surfaces)
            if (box.surface[s])
                box.line[l] = true;
    box.corner.resize(model.corners.size());
    for (std::size_t c = 0; c < model.corners.size(); ++c)
        box.corner[c] = boxVertex[model.corners[c].vertex];
    return box;
}

Box3 modelBounds(const Model &model)
{
    Box3 bounds;
    for (const Surface &s : model.surfaces)
        for (const Vec3 &p : s.vertices)
            bounds.extend(p);
    return bounds;
}

} // namespace stratamesh
