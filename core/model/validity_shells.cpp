// folded_contact and region_pocket (region_shells.h): the region sides agree with the geometry.
#include "common/translate_noop.h"
#include "model/region_shells.h"
#include "model/validity_checks.h"

#include <cstdio>
#include <set>

namespace stratamesh::validity_detail {

void checkRegionShells(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    const RegionShells shells = analyseRegionShells(model);
    auto regionName = [&](int r) {
        return r < static_cast<int>(model.regions.size()) ? model.regions[r].name
                                                          : std::string("Universe");
    };
    for (const FoldedContact &f : shells.folds) {
        const std::string &a = model.surfaces[f.surfaceA].name,
                          &b = model.surfaces[f.surfaceB].name;
        const Vec3 at = edgeMidpoint(model, f.edge);
        sink.add(validity_check::foldedContact,
                 {a, b, regionName(f.regionA), regionName(f.regionB)}, at,
                 {QT_TRANSLATE_NOOP("stratamesh::Core",
                                    "surfaces %1 and %2 fold over each other at %3: one space "
                                    "between them is on the side of %4 and of %5"),
                  {a, b, pointText(at), regionName(f.regionA), regionName(f.regionB)}});
    }
    for (const RegionPocket &pocket : shells.pockets) {
        std::set<int> surfaces;
        for (const PocketSide &side : pocket.sides)
            surfaces.insert(side.surface);
        std::vector<std::string> entities{model.regions[pocket.region].name};
        std::string names;
        for (int s : surfaces) {
            entities.push_back(model.surfaces[s].name);
            names += (names.empty() ? "" : ", ") + model.surfaces[s].name;
        }
        char volume[32];
        std::snprintf(volume, sizeof volume, "%.3g", pocket.volume);
        sink.add(validity_check::regionPocket, entities, pocket.centre,
                 {QT_TRANSLATE_NOOP("stratamesh::Core",
                                    "region %1 is in more than one piece: a pocket of volume %2 "
                                    "between %3 at %4 is cut off from it"),
                  {model.regions[pocket.region].name, volume, names, pointText(pocket.centre)}});
    }
}

} // namespace stratamesh::validity_detail
