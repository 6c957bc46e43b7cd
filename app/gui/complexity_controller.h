// The "complexity" workflow: computeComplexity() (thesis ch. 3, as `stratamesh-cli complexity`)
// on the loaded model for one number of cells, in a worker thread, reporting progress,
// cancellable at the engine's next progress tick. The model is shared read-only.
#pragma once

#include "complexity_outcome.h"

#include <QFutureWatcher>
#include <QObject>

#include <memory>

namespace stratamesh {

class Progress;

class ComplexityController : public QObject {
    Q_OBJECT
public:
    explicit ComplexityController(QObject *parent = nullptr);
    ~ComplexityController() override;

    // Returns immediately; false when busy, without a model, or without exactly one number of
    // cells in params.cells.
    bool start(std::shared_ptr<const Model> model, const ComplexityParams &params);
    // Asks the engine to stop; cancelled() follows once the worker has returned.
    void cancel();
    bool isBusy() const { return m_pending; }
    // Blocks until the current run, if any, has finished and its signals were emitted.
    void waitForFinished();

signals:
    void started();
    void progressChanged(int percent, const QString &stage);
    void succeeded(const stratamesh::ComplexityOutcome &outcome);
    void failed(const stratamesh::Message &error);
    void cancelled();
    void finished(bool ok);

private:
    void onFinished();

    QFutureWatcher<ComplexityRun> m_watcher;
    std::shared_ptr<Progress> m_progress;
    bool m_pending = false;
    int m_percent = 0; // last percentage reported in this run
};

} // namespace stratamesh
