// The "open model" workflow: read the file (or build the sample), recover topology and check
// validity in a worker thread, reporting progress; the window only shows the outcome.
#pragma once

#include "loaded_model.h"
#include "workflow_job.h"

#include <QFutureWatcher>

namespace stratamesh {

class OpenModelController : public WorkflowJob {
    Q_OBJECT
public:
    explicit OpenModelController(QObject *parent = nullptr);
    ~OpenModelController() override;

    // Both return immediately; one load at a time (a new request while busy is refused).
    bool openFile(const QString &path);
    bool openSample();

    // File dialog filter of the formats the reader understands.
    static QString fileFilter();

signals:
    // Before started(): the name the window shows while the model is read.
    void opening(const QString &displayName);
    void loaded(const stratamesh::LoadedModel &model);

private:
    bool start(const QString &path, const QString &displayName);
    void onFinished();

    QFutureWatcher<LoadResult> m_watcher;
};

} // namespace stratamesh
