#include "remesh/ledger_reconciliation.h"

#include "remesh/output_model_builder.h"
#include "remesh/topology_refinement.h"

#include <algorithm>
#include <limits>

namespace stratamesh {

namespace {

// Where an entity record's entity lies: its position, and the vertices of a line it names.
std::vector<Vec3> recordPlaces(const Model &input, const Model &output, const LedgerRecord &r)
{
    std::vector<Vec3> places{r.position};
    auto addLine = [&places](const Model &m, const EntityRef &ref) {
        if (ref.kind == EntityKind::Line && ref.id >= 0
            && ref.id < static_cast<int>(m.lines.size()))
            for (int v : m.lines[ref.id].vertices)
                places.push_back(m.vertices[v]);
    };
    for (const EntityRef &ref : r.inputs)
        addLine(input, ref);
    for (const EntityRef &ref : r.outputs)
        addLine(output, ref);
    return places;
}

} // namespace

void reconcileLedger(const Model &input, const Model &output, SimplificationLedger &ledger,
                     double reach, std::size_t inputNumbered)
{
    SimplificationLedger kept;
    std::vector<std::vector<Vec3>> causePlaces;
    for (std::size_t i = 0; i < ledger.size(); ++i) {
        if (isTopologyEdit(ledger[i].kind))
            continue;
        std::vector<Vec3> places{ledger[i].position};
        if (i < inputNumbered)
            for (const EntityRef &ref : ledger[i].inputs)
                if (ref.kind == EntityKind::Line && ref.id >= 0
                    && ref.id < static_cast<int>(input.lines.size()))
                    for (int v : input.lines[ref.id].vertices)
                        places.push_back(input.vertices[v]);
        causePlaces.push_back(std::move(places));
        kept.push_back(std::move(ledger[i]));
    }
    const std::size_t firstEdit = kept.size();
    recordEntityChanges(input, output, kept);
    const double reach2 = reach * reach;
    for (std::size_t i = firstEdit; i < kept.size(); ++i) {
        const std::vector<Vec3> places = recordPlaces(input, output, kept[i]);
        double best = std::numeric_limits<double>::max();
        for (std::size_t c = 0; c < firstEdit; ++c)
            for (const Vec3 &q : causePlaces[c])
                for (const Vec3 &p : places) {
                    const double d2 = (q - p).squaredNorm();
                    if (d2 <= reach2 && d2 < best) {
                        best = d2;
                        kept[i].cause = static_cast<int>(c);
                    }
                }
    }
    ledger = std::move(kept);
}

LedgerBalance ledgerBalance(const Model &input, const Model &output,
                            const SimplificationLedger &ledger)
{
    LedgerBalance b;
    b.surfaces.input = static_cast<int>(input.surfaces.size());
    b.surfaces.output = static_cast<int>(output.surfaces.size());
    b.lines.input = static_cast<int>(input.lines.size());
    b.lines.output = static_cast<int>(output.lines.size());
    b.corners.input = static_cast<int>(input.corners.size());
    b.corners.output = static_cast<int>(output.corners.size());
    for (const LedgerRecord &r : ledger)
        switch (r.kind) {
        case LedgerKind::SurfaceLost:
            ++b.surfaces.lost;
            break;
        case LedgerKind::SurfaceCreated:
            ++b.surfaces.created;
            break;
        case LedgerKind::LineLost:
            ++b.lines.lost;
            break;
        case LedgerKind::LineCreated:
            ++b.lines.created;
            break;
        case LedgerKind::CornerLost:
            ++b.corners.lost;
            break;
        case LedgerKind::CornerCreated:
            ++b.corners.created;
            break;
        default:
            break;
        }
    return b;
}

} // namespace stratamesh
