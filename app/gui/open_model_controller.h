// The "open model" workflow: read the file (or build the sample), recover topology and check
// validity in a worker thread, reporting progress; the window only shows the outcome.
#pragma once

#include "loaded_model.h"

#include <QFutureWatcher>
#include <QObject>

namespace stratamesh {

class OpenModelController : public QObject {
    Q_OBJECT
public:
    explicit OpenModelController(QObject *parent = nullptr);
    ~OpenModelController() override;

    // Both return immediately; one load at a time (a new request while busy is refused).
    bool openFile(const QString &path);
    bool openSample();
    bool isBusy() const;
    // Blocks until the current load, if any, has finished and its signals were emitted.
    void waitForFinished();

    // File dialog filter of the formats the reader understands.
    static QString fileFilter();

signals:
    void started(const QString &displayName);
    void progressChanged(int percent, const QString &stage);
    void loaded(const stratamesh::LoadedModel &model);
    void failed(const stratamesh::Message &error);
    void finished(bool ok);

private:
    bool start(const QString &path, const QString &displayName);
    void onFinished();

    QFutureWatcher<LoadResult> m_watcher;
    bool m_pending = false; // from start() until finished() was emitted
};

} // namespace stratamesh
