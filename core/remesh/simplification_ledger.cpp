#include "remesh/simplification_ledger.h"

#include <algorithm>

namespace stratamesh {

std::string ledgerKindName(LedgerKind kind)
{
    switch (kind) {
    case LedgerKind::CornerMerge:
        return "corner_merge";
    case LedgerKind::MultiPointMerge:
        return "multi_point_merge";
    case LedgerKind::CloseFeatureMerge:
        return "close_feature_merge";
    case LedgerKind::DegenerateContactTriangle:
        return "degenerate_contact_triangle";
    case LedgerKind::DegenerateBorderTriangle:
        return "degenerate_border_triangle";
    case LedgerKind::Valence3Removed:
        return "valence3_removed";
    case LedgerKind::SurfaceLost:
        return "surface_lost";
    case LedgerKind::LineLost:
        return "line_lost";
    case LedgerKind::CornerLost:
        return "corner_lost";
    case LedgerKind::SurfaceCreated:
        return "surface_created";
    case LedgerKind::LineCreated:
        return "line_created";
    case LedgerKind::CornerCreated:
        return "corner_created";
    case LedgerKind::IntersectionUnresolved:
        return "intersection_unresolved";
    case LedgerKind::SurfacePartLost:
        return "surface_part_lost";
    case LedgerKind::SurfacePartCreated:
        return "surface_part_created";
    }
    return "unknown";
}

std::string entityKindName(EntityKind kind)
{
    switch (kind) {
    case EntityKind::Surface:
        return "surface";
    case EntityKind::Line:
        return "line";
    case EntityKind::Corner:
        return "corner";
    case EntityKind::Vertex:
        return "vertex";
    }
    return "unknown";
}

EntityRef surfaceRef(const Model &model, int surface)
{
    EntityRef r{EntityKind::Surface, surface, {}};
    if (surface >= 0 && surface < static_cast<int>(model.surfaces.size()))
        r.name = model.surfaces[surface].name;
    return r;
}

EntityRef lineRef(const Model &model, int line)
{
    EntityRef r{EntityKind::Line, line, {}};
    if (line >= 0 && line < static_cast<int>(model.lines.size()))
        r.name = model.lines[line].name;
    if (r.name.empty())
        r.name = "line_" + std::to_string(line);
    return r;
}

EntityRef cornerRef(const Model &, int corner)
{
    return EntityRef{EntityKind::Corner, corner, "corner_" + std::to_string(corner)};
}

EntityRef vertexRef(int vertex)
{
    return EntityRef{EntityKind::Vertex, vertex, "vertex_" + std::to_string(vertex)};
}

void addUnique(std::vector<EntityRef> &refs, const EntityRef &ref)
{
    if (std::find(refs.begin(), refs.end(), ref) == refs.end())
        refs.push_back(ref);
}

int countKind(const SimplificationLedger &ledger, LedgerKind kind)
{
    return static_cast<int>(std::count_if(
        ledger.begin(), ledger.end(), [kind](const LedgerRecord &r) { return r.kind == kind; }));
}

} // namespace stratamesh
