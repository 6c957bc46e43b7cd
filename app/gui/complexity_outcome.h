// What the complexity workflow hands to the window: the measures of thesis chapter 3 for one
// number of cells (Tables 3.1–3.4) with the cells and their counts for the heat map (Fig 3.7).
#pragma once

#include "complexity/complexity_report.h"
#include "message.h"
#include "model/model.h"
#include "workflow_job.h"

#include <QMetaType>

#include <memory>

namespace stratamesh {

struct ComplexityOutcome {
    std::shared_ptr<const Model> model;             // the model that was measured, unchanged
    ComplexityParams params;                        // params.cells holds the one number of cells
    std::shared_ptr<const ComplexityReport> report; // report->local has one entry
    // The cells of report->local[0].cvt.cells, shared with the heat map.
    std::shared_ptr<const std::vector<ConvexPolyhedron>> cells;
    qint64 milliseconds = 0;

    const LocalComplexity &local() const { return report->local.front(); }
};

struct ComplexityRun {
    using Status = RunStatus;
    Status status = Status::Failed;
    ComplexityOutcome outcome; // when Done
    Message error;             // when Failed
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::ComplexityOutcome)
