// What the window's background workflows share (open, remesh, complexity, tetmesh): one run at a
// time in a worker thread, one root Progress whose ticks (from any thread, TBB workers included)
// reach progressChanged() in the GUI thread as a percentage that only moves forward and the
// stage chain ("Remeshing: Mesh building: dual faces (4/7)"), cancel at the engine's next
// progress tick, and the end of a run told by signals once the worker has returned.
#pragma once

#include "message.h"

#include <QFutureWatcher>
#include <QObject>

#include <functional>
#include <memory>

namespace stratamesh {

class Progress;

enum class RunStatus { Done, Cancelled, Failed };

class WorkflowJob : public QObject {
    Q_OBJECT
public:
    explicit WorkflowJob(QObject *parent = nullptr);
    ~WorkflowJob() override;

    // Asks the engine to stop; cancelled() follows once the worker has returned.
    void cancel();
    bool isBusy() const { return m_pending; }
    // Blocks until the current run, if any, has finished and its signals were emitted.
    void waitForFinished();

signals:
    void started();
    void progressChanged(int percent, const QString &stage);
    void failed(const stratamesh::Message &error);
    void cancelled();
    void finished(bool ok);

protected:
    // The root progress of a new run (started() is emitted), whose ticks are relayed to
    // progressChanged() as "title: stage"; nullptr while a run is under way.
    std::shared_ptr<Progress> begin(const QString &title = QString());
    // Once the worker has returned: emitSucceeded() for a finished run, cancelled() or failed(),
    // then finished().
    void end(RunStatus status, const Message &error, const std::function<void()> &emitSucceeded);
    // Cancels the worker and waits for it; derived destructors call it before their watcher goes.
    void stop(QFutureWatcherBase &watcher);

private:
    std::shared_ptr<Progress> m_progress;
    bool m_pending = false;
    int m_percent = 0; // last percentage reported in this run
    int m_run = 0;     // numbers the runs: a late tick of a finished run is dropped
};

} // namespace stratamesh
