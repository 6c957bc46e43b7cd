#include "export_controller.h"

#include "common/progress.h"
#include "error_message.h"
#include "io/mesh_writer.h"
#include "io/output_plan.h"

#include <QElapsedTimer>
#include <QPromise>
#include <QtConcurrent>

namespace stratamesh {

namespace {

// Runs in the worker thread. The writers take no progress: the run cannot be cancelled.
void runExport(QPromise<ExportRun> &promise, ExportRequest request)
{
    QElapsedTimer timer;
    timer.start();
    ExportRun run;
    try {
        const std::string path = request.path.toStdString();
        OutputPlan plan({request.inputPath.toStdString()});
        plan.add(path, request.role.toStdString());
        plan.write(path, [&](const std::string &temporary) {
            run.report = request.model
                             ? exportModel(*request.model, temporary, request.options)
                             : exportVolumeMesh(*request.mesh, temporary, request.options);
        });
        plan.commit();
        run.status = RunStatus::Done;
    } catch (const std::exception &e) {
        run.error = errorMessage(e, request.path);
    }
    run.milliseconds = timer.elapsed();
    promise.addResult(std::move(run));
}

} // namespace

ExportController::ExportController(QObject *parent) : WorkflowJob(parent)
{
    connect(&m_watcher, &QFutureWatcher<ExportRun>::finished, this, &ExportController::onFinished);
}

ExportController::~ExportController()
{
    stop(m_watcher);
}

bool ExportController::start(const ExportRequest &request)
{
    if (!request.model && !request.mesh)
        return false;
    if (!begin(tr("Exporting")))
        return false;
    m_path = request.path;
    m_watcher.setFuture(QtConcurrent::run(&runExport, request));
    return true;
}

void ExportController::onFinished()
{
    const QFuture<ExportRun> future = m_watcher.future();
    ExportRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {
            Message::Severity::Error, tr("The export stopped without a result"), m_path, 0, {}};
    end(run.status, run.error, [&] {
        emit succeeded(m_path, QString::fromStdString(run.report.format),
                       qulonglong(run.report.untaggedSkipped), run.milliseconds);
    });
}

} // namespace stratamesh
