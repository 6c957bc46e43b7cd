// The "remesh" workflow: remeshModel() then compareModels() on the loaded model in a worker
// thread, reporting progress, cancellable at the engine's next progress tick. The input model is
// shared read-only and never changed; the window only shows the outcome.
#pragma once

#include "remesh_outcome.h"
#include "workflow_job.h"

#include <QFutureWatcher>

#include <memory>

namespace stratamesh {

class RemeshController : public WorkflowJob {
    Q_OBJECT
public:
    explicit RemeshController(QObject *parent = nullptr);
    ~RemeshController() override;

    // Returns immediately; false when busy or without a model.
    bool start(std::shared_ptr<const Model> input, const RemeshParams &params);

    // Hausdorff samples per side for the comparison: fewer than the CLI's report, as the GUI
    // shows 3 decimals of a percentage and must answer quickly.
    static constexpr int kHausdorffSamples = 50000;

signals:
    void succeeded(const stratamesh::RemeshOutcome &outcome);

private:
    void onFinished();

    QFutureWatcher<RemeshRun> m_watcher;
};

} // namespace stratamesh
