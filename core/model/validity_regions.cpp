// region_boundary: each region is "completely defined by the set of surfaces constituting its
// boundary" (thesis §3.2). With the sides of formats.md §0 (positive: the region is on the side
// the normal points to), the boundary of a region, each triangle turned to face the region, must
// be a closed, consistently oriented shell: every edge is run as often one way as the other. Its
// volume must then be positive (negative for the Universe). A surface listed with both signs lies
// inside the region and is left out. Each side of a surface belongs to at most one region.
#include "common/translate_noop.h"
#include "model/region_volume.h"
#include "model/validity_checks.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace stratamesh::validity_detail {

namespace {

Vec3 surfaceCentre(const Model &model, int s)
{
    const Surface &surface = model.surfaces[s];
    Vec3 c = Vec3::Zero();
    for (const Vec3 &p : surface.vertices)
        c += p;
    return surface.vertices.empty() ? c : Vec3(c / static_cast<double>(surface.vertices.size()));
}

std::string numberText(double v)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

struct SideOwner {
    std::string name;
    const std::vector<RegionSide> *sides;
    bool universe;
};

void checkShell(const Model &model, const SideOwner &owner, ProblemSink &sink)
{
    if (owner.sides->empty()) {
        if (!owner.universe)
            sink.add(validity_check::regionBoundary, {owner.name}, Vec3::Zero(),
                     {QT_TRANSLATE_NOOP("stratamesh::Core", "region %1 has no boundary surface"),
                      {owner.name}});
        return;
    }
    std::vector<RegionSide> sides = *owner.sides;
    std::sort(sides.begin(), sides.end(), [](const RegionSide &a, const RegionSide &b) {
        return a.surface != b.surface ? a.surface < b.surface : a.positive < b.positive;
    });
    struct Use {
        long long key;
        int direction; // +1 when run from the smaller to the larger global id, facing the region
        int surface;
    };
    std::vector<Use> uses;
    bool anyOneSided = false;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const int s = sides[i].surface;
        if (i > 0 && sides[i] == sides[i - 1]) {
            sink.add(validity_check::regionBoundary, {owner.name, model.surfaces[s].name},
                     surfaceCentre(model, s),
                     {QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "%1 lists the same side of surface %2 twice"),
                      {owner.name, model.surfaces[s].name}});
            continue;
        }
        const bool both = (i > 0 && sides[i - 1].surface == s)
                          || (i + 1 < sides.size() && sides[i + 1].surface == s);
        if (both)
            continue;
        anyOneSided = true;
        const std::vector<int> &g = model.surfaceVertexToGlobal[s];
        for (const Triangle &t : model.surfaces[s].triangles)
            for (int k = 0; k < 3; ++k) {
                const int a = g[t[k]], b = g[t[(k + 1) % 3]];
                if (a == b)
                    continue;
                const int direction = (a < b) == sides[i].positive ? 1 : -1;
                uses.push_back({edgeKey(a, b), direction, s});
            }
    }
    std::sort(uses.begin(), uses.end(), [](const Use &x, const Use &y) { return x.key < y.key; });
    std::size_t open = 0, unbalanced = 0;
    const Use *firstOpen = nullptr, *firstUnbalanced = nullptr;
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        int balance = 0;
        for (; j < uses.size() && uses[j].key == uses[i].key; ++j)
            balance += uses[j].direction;
        if ((j - i) % 2 == 1) {
            firstOpen = firstOpen ? firstOpen : &uses[i];
            ++open;
        } else if (balance != 0) {
            firstUnbalanced = firstUnbalanced ? firstUnbalanced : &uses[i];
            ++unbalanced;
        }
        i = j;
    }
    if (open > 0)
        sink.add(validity_check::regionBoundary,
                 {owner.name, model.surfaces[firstOpen->surface].name},
                 edgeMidpoint(model, firstOpen->key),
                 {owner.universe ? QT_TRANSLATE_NOOP("stratamesh::Core",
                                                     "the boundary of the Universe is not closed: "
                                                     "%1 edges are used an odd number of times")
                                 : QT_TRANSLATE_NOOP("stratamesh::Core",
                                                     "the boundary of region %2 is not closed: %1 "
                                                     "edges are used an odd number of times"),
                  {std::to_string(open), owner.name}});
    if (unbalanced > 0)
        sink.add(validity_check::regionBoundary,
                 {owner.name, model.surfaces[firstUnbalanced->surface].name},
                 edgeMidpoint(model, firstUnbalanced->key),
                 {owner.universe
                      ? QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "the sides of the Universe are inconsistent: %1 edges "
                                          "are not run as often one way as the other")
                      : QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "the sides of region %2 are inconsistent: %1 edges are "
                                          "not run as often one way as the other"),
                  {std::to_string(unbalanced), owner.name}});
    if (open == 0 && unbalanced == 0 && anyOneSided) {
        const double volume = sidesVolume(model, *owner.sides);
        if (owner.universe ? volume >= 0.0 : volume <= 0.0)
            sink.add(
                validity_check::regionBoundary, {owner.name},
                surfaceCentre(model, owner.sides->front().surface),
                {owner.universe
                     ? QT_TRANSLATE_NOOP("stratamesh::Core",
                                         "the sides of the Universe disagree with the surface "
                                         "normals: its volume is %1 (expected negative; region on "
                                         "the side the normal points to is '+')")
                     : QT_TRANSLATE_NOOP(
                         "stratamesh::Core",
                         "the sides of region %2 disagree with the surface normals: its volume is "
                         "%1 (expected positive; region on the side the normal points to is '+')"),
                 {numberText(volume), owner.name}});
    }
}

void checkSideOwnership(const Model &model, const std::vector<SideOwner> &owners, ProblemSink &sink)
{
    std::map<std::pair<int, bool>, std::vector<std::size_t>> claims;
    for (std::size_t o = 0; o < owners.size(); ++o)
        for (const RegionSide &side : *owners[o].sides) {
            std::vector<std::size_t> &c = claims[{side.surface, side.positive}];
            if (std::find(c.begin(), c.end(), o) == c.end())
                c.push_back(o);
        }
    for (const auto &[side, owning] : claims)
        if (owning.size() > 1) {
            std::vector<std::string> names{model.surfaces[side.first].name};
            for (std::size_t o : owning)
                names.push_back(owners[o].name);
            sink.add(validity_check::regionBoundary, names, surfaceCentre(model, side.first),
                     {QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "side %1 of surface %2 is claimed by %3 regions"),
                      {side.second ? "+" : "-", model.surfaces[side.first].name,
                       std::to_string(owning.size())}});
        }
    // With the Universe given, every side of every surface belongs to exactly one region.
    const bool universeGiven = owners.size() > model.regions.size();
    if (!universeGiven || model.regions.empty())
        return;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        for (bool positive : {true, false})
            if (!claims.count({static_cast<int>(s), positive}))
                sink.add(validity_check::regionBoundary, {model.surfaces[s].name},
                         surfaceCentre(model, static_cast<int>(s)),
                         {QT_TRANSLATE_NOOP(
                              "stratamesh::Core",
                              "side %1 of surface %2 belongs to no region nor to the Universe"),
                          {positive ? "+" : "-", model.surfaces[s].name}});
}

} // namespace

void checkRegionBoundaries(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    std::vector<SideOwner> owners;
    for (const Region &r : model.regions)
        owners.push_back({r.name, &r.boundaries, false});
    if (!model.universe.empty())
        owners.push_back({"Universe", &model.universe, true});
    for (const SideOwner &o : owners)
        checkShell(model, o, sink);
    checkSideOwnership(model, owners, sink);
}

} // namespace stratamesh::validity_detail
