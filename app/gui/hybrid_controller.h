// The hybrid mesh workflow's run: buildHybridMesh() (core/hybrid) on the open model in a worker
// thread, with progress; a cancel stops the engine at its next tick (and kills the TetGen helper
// of the fill). The model is shared read-only.
#pragma once

#include "hybrid_outcome.h"
#include "workflow_job.h"

#include <QFutureWatcher>

#include <memory>

namespace stratamesh {

class HybridController : public WorkflowJob {
    Q_OBJECT
public:
    explicit HybridController(QObject *parent = nullptr);
    ~HybridController() override;

    // Returns immediately; false when busy or without a model.
    bool start(std::shared_ptr<const Model> model, const HybridParams &params);

signals:
    void succeeded(const stratamesh::HybridOutcome &outcome);

private:
    void onFinished();

    QFutureWatcher<HybridRun> m_watcher;
};

} // namespace stratamesh
