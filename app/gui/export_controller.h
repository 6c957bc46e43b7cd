// File > Export…'s run: one model or volume mesh written in a worker thread through an output plan
// (io/output_plan.h) as the command line's convert does — checked first, written to a temporary
// beside the target and renamed, never over the open model's file. A large volume mesh takes
// seconds to write as VTK or Gmsh; the window stays live meanwhile. The data is shared read-only.
#pragma once

#include "io/formats.h"
#include "workflow_job.h"

#include <QFutureWatcher>
#include <QString>

#include <memory>

namespace stratamesh {

struct ExportRequest {
    std::shared_ptr<const Model> model;     // a surface model, or
    std::shared_ptr<const VolumeMesh> mesh; // a volume mesh
    QString path;
    QString inputPath; // the open model's file: refused as the target
    QString role;      // "remeshed model", ... in messages of the plan
    ExportOptions options;
};

struct ExportRun {
    RunStatus status = RunStatus::Failed;
    ExportReport report; // when Done
    Message error;       // when Failed
    qint64 milliseconds = 0;
};

class ExportController : public WorkflowJob {
    Q_OBJECT
public:
    explicit ExportController(QObject *parent = nullptr);
    ~ExportController() override;

    // Returns immediately; false when busy or with nothing to write.
    bool start(const ExportRequest &request);

signals:
    // format: the writer's name ("Gmsh MSH 4.1"); untaggedSkipped: see ExportReport.
    void succeeded(const QString &path, const QString &format, qulonglong untaggedSkipped,
                   qint64 milliseconds);

private:
    void onFinished();

    QFutureWatcher<ExportRun> m_watcher;
    QString m_path;
};

} // namespace stratamesh
