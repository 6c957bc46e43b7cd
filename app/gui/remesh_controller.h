// The "remesh" workflow: remeshModel() then compareModels() on the loaded model in a worker
// thread, reporting progress, cancellable at the engine's next progress tick. The input model is
// shared read-only and never changed; the window only shows the outcome.
#pragma once

#include "remesh_outcome.h"

#include <QFutureWatcher>
#include <QObject>

#include <memory>

namespace stratamesh {

class Progress;

class RemeshController : public QObject {
    Q_OBJECT
public:
    explicit RemeshController(QObject *parent = nullptr);
    ~RemeshController() override;

    // Returns immediately; false when busy or without a model.
    bool start(std::shared_ptr<const Model> input, const RemeshParams &params);
    // Asks the engine to stop; cancelled() follows once the worker has returned.
    void cancel();
    bool isBusy() const { return m_pending; }
    // Blocks until the current run, if any, has finished and its signals were emitted.
    void waitForFinished();

    // Hausdorff samples per side for the comparison: fewer than the CLI's report, as the GUI
    // shows 3 decimals of a percentage and must answer quickly.
    static constexpr int kHausdorffSamples = 50000;

signals:
    void started();
    void progressChanged(int percent, const QString &stage);
    void succeeded(const stratamesh::RemeshOutcome &outcome);
    void failed(const stratamesh::Message &error);
    void cancelled();
    void finished(bool ok);

private:
    void onFinished();

    QFutureWatcher<RemeshRun> m_watcher;
    std::shared_ptr<Progress> m_progress;
    bool m_pending = false;
    int m_percent = 0; // last percentage reported in this run
};

} // namespace stratamesh
