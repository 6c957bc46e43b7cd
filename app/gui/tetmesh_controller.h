// The "tetrahedralise" workflow: TetGen on the input model and on its remesh (or on the input
// alone) in a worker thread, with progress; a cancel stops the engine at its next tick, which
// kills the TetGen helper process (volume/tetgen_runner.h). The models are shared read-only.
#pragma once

#include "tetmesh_outcome.h"
#include "workflow_job.h"

#include <QFutureWatcher>

#include <memory>

namespace stratamesh {

class TetmeshController : public WorkflowJob {
    Q_OBJECT
public:
    explicit TetmeshController(QObject *parent = nullptr);
    ~TetmeshController() override;

    // Returns immediately; false when busy or without an input. output nullptr: the input alone.
    bool start(std::shared_ptr<const Model> input, std::shared_ptr<const Model> output,
               const TetgenParams &params);

signals:
    void succeeded(const stratamesh::TetmeshOutcome &outcome);

private:
    void onFinished();

    QFutureWatcher<TetmeshRun> m_watcher;
};

} // namespace stratamesh
