// not_sealed: surfaces must meet along their borders (thesis §3.2: surfaces are bounded by lines
// that are "at the intersection of several surfaces, or on the boundary of only one surface").
// A border touching nothing is only legitimate for a surface lying inside one region (a dangling
// fault or a horizon ending inside a layer, Fig 3.1 surface F4), i.e. listed there with both signs.
#include "common/translate_noop.h"
#include "model/validity_checks.h"

namespace stratamesh::validity_detail {

void checkSealed(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    std::vector<char> insideRegion(model.surfaces.size(), 0);
    for (const Region &r : model.regions)
        for (const RegionSide &a : r.boundaries)
            for (const RegionSide &b : r.boundaries)
                if (a.surface == b.surface && a.positive != b.positive)
                    insideRegion[a.surface] = 1;

    for (const Line &line : model.lines) {
        if (line.surfaces.size() != 1 || insideRegion[line.surfaces[0]])
            continue;
        const std::size_t n = line.vertices.size();
        const std::size_t edgeCount = line.closed ? n : n - 1;
        std::size_t free = 0;
        long long firstFree = 0;
        for (std::size_t i = 0; i < edgeCount; ++i) {
            const long long key = edgeKey(line.vertices[i], line.vertices[(i + 1) % n]);
            auto [first, last] = edgesWithKey(in.edges, key);
            if (last - first == 1 && first->triangles == 1) {
                if (free == 0)
                    firstFree = key;
                ++free;
            }
        }
        if (free == 0)
            continue;
        const std::string &surface = model.surfaces[line.surfaces[0]].name;
        sink.add(
            validity_check::notSealed, {surface, line.name}, edgeMidpoint(model, firstFree),
            {QT_TRANSLATE_NOOP("stratamesh::Core",
                               "%1 of the %2 edges of %3 are on the border of surface %4 only: the "
                               "model is not sealed there (it touches no other surface)"),
             {std::to_string(free), std::to_string(edgeCount), line.name, surface}});
    }
}

} // namespace stratamesh::validity_detail
