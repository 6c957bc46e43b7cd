// The ledger adds up (thesis §4.6.1: "a quality check of the disappearing and appearing elements
// is necessary"): the entities lost and created are counted between the model the user gave and
// the output, not between intermediate steps (thin-strip removal, refinement rounds), so that for
// surfaces, lines and corners input − lost + created = output. Each lost or created entity names
// the simplification that caused it, or none: then it is an artefact of the resolution.
#pragma once

#include "remesh/simplification_ledger.h"

namespace stratamesh {

// Replaces the entity records of `ledger` (surfaces, surface parts, lines and corners lost or
// created) by those between `input` and `output` (both with topology), then sets their cause:
// the nearest other record within `reach` of the entity (any of its line vertices for lines).
// The first `inputNumbered` records name lines with the input's numbering (thin-strip removal,
// before remeshing): such a record stands for all of its lines (a strip's ends lose corners far
// from its middle).
void reconcileLedger(const Model &input, const Model &output, SimplificationLedger &ledger,
                     double reach, std::size_t inputNumbered = 0);

struct EntityBalance {
    int input = 0, lost = 0, created = 0, output = 0;
    bool balanced() const { return input - lost + created == output; }
};
struct LedgerBalance {
    EntityBalance surfaces, lines, corners;
    bool balanced() const { return surfaces.balanced() && lines.balanced() && corners.balanced(); }
};

// The counts of the `info` report (box included) against the ledger's records.
LedgerBalance ledgerBalance(const Model &input, const Model &output,
                            const SimplificationLedger &ledger);

} // namespace stratamesh
