// The "complexity" workflow: computeComplexity() (thesis ch. 3, as `stratamesh-cli complexity`)
// on the loaded model for one number of cells, in a worker thread, reporting progress,
// cancellable at the engine's next progress tick. The model is shared read-only.
#pragma once

#include "complexity_outcome.h"
#include "workflow_job.h"

#include <QFutureWatcher>

#include <memory>

namespace stratamesh {

class ComplexityController : public WorkflowJob {
    Q_OBJECT
public:
    explicit ComplexityController(QObject *parent = nullptr);
    ~ComplexityController() override;

    // Returns immediately; false when busy, without a model, or without exactly one number of
    // cells in params.cells.
    bool start(std::shared_ptr<const Model> model, const ComplexityParams &params);

signals:
    void succeeded(const stratamesh::ComplexityOutcome &outcome);

private:
    void onFinished();

    QFutureWatcher<ComplexityRun> m_watcher;
};

} // namespace stratamesh
