#include "support/model_lines.h"

namespace stratamesh::test {

int countLines(const Model &model, const std::function<bool(int horizons, int faults)> &accept)
{
    int n = 0;
    for (const Line &l : model.lines) {
        int horizons = 0, faults = 0;
        for (int s : l.surfaces) {
            horizons += model.surfaces[s].type == FeatureType::Horizon ? 1 : 0;
            faults += model.surfaces[s].type == FeatureType::Fault ? 1 : 0;
        }
        n += accept(horizons, faults) ? 1 : 0;
    }
    return n;
}

} // namespace stratamesh::test
