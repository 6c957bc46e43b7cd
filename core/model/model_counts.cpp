#include "model/model_counts.h"

#include "common/error.h"

#include <vector>

namespace stratamesh {

ModelCounts countEntities(const Model &model)
{
    if (!model.hasTopology() && !model.surfaces.empty())
        throw InputError("entity counts need the model topology (recoverTopology)");
    ModelCounts c;
    c.all = {static_cast<int>(model.regions.size()), static_cast<int>(model.surfaces.size()),
             static_cast<int>(model.lines.size()), static_cast<int>(model.corners.size())};
    c.withoutBox.regions = c.all.regions;

    std::vector<char> onBox(model.vertices.size(), 0);
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        if (!isBoxSurface(model.surfaces[s])) {
            ++c.withoutBox.surfaces;
            continue;
        }
        for (int g : model.surfaceVertexToGlobal[s])
            onBox[g] = 1;
    }
    for (const Line &line : model.lines) {
        bool box = false;
        for (int s : line.surfaces)
            box = box || isBoxSurface(model.surfaces[s]);
        if (!box)
            ++c.withoutBox.lines;
    }
    for (const Corner &corner : model.corners)
        if (!onBox[corner.vertex])
            ++c.withoutBox.corners;
    return c;
}

} // namespace stratamesh
