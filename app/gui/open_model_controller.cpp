#include "open_model_controller.h"

#include "error_message.h"
#include "validity_messages.h"

#include "common/error.h"
#include "common/progress.h"
#include "io/formats.h"
#include "io/model_reader.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_topology.h"
#include "model/model_counts.h"
#include "model/synthetic_models.h"
#include "model/topology.h"
#include "model/validity.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QPromise>
#include <QtConcurrent>

namespace stratamesh {

namespace {

// Runs in the worker thread: everything here is core work, plus conversion into messages.
void loadModel(QPromise<LoadResult> &promise, const QString &path, const QString &displayName,
               std::shared_ptr<Progress> progress)
{
    QElapsedTimer timer;
    timer.start();
    LoadResult result;
    result.loaded.path = path;
    result.loaded.displayName = displayName;
    const std::string file = path.toStdString();
    try {
        Model model;
        if (path.isEmpty()) {
            progress->tick(0.05,
                           OpenModelController::tr("Building the sample model").toStdString());
            model = sampleModel();
        } else {
            progress->tick(0.05,
                           OpenModelController::tr("Reading %1").arg(displayName).toStdString());
            model = readModel(file);
        }
        progress->tick(0.6, OpenModelController::tr("Recovering lines and corners").toStdString());
        model = recoverTopology(std::move(model));
        {
            Progress checking(*progress, 0.85, 0.99,
                              OpenModelController::tr("Checking validity").toStdString());
            checking.tick(0.0);
            ValidityReport report = checkValidity(model, checking);
            if (isRingMeshFile(file)) // a GeoModel also states its lines and corners
                addRingMeshTopologyProblems(file, model, report);
            result.loaded.messages = validityMessages(report, path);
        }
        if (promise.isCanceled())
            throw Cancelled(); // the window is closing
        result.loaded.counts = countEntities(model);
        result.loaded.model = std::make_shared<const Model>(std::move(model));
        result.ok = true;
    } catch (const Cancelled &) {
        result.cancelled = true;
    } catch (const std::exception &e) {
        result.error = errorMessage(e, path);
    }
    result.loaded.milliseconds = timer.elapsed();
    promise.addResult(std::move(result));
}

} // namespace

OpenModelController::OpenModelController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::LoadedModel>();
    connect(&m_watcher, &QFutureWatcher<LoadResult>::finished, this,
            &OpenModelController::onFinished);
}

// The validity check stops at its next progress tick; the reader cannot be interrupted.
OpenModelController::~OpenModelController()
{
    stop(m_watcher);
}

QString OpenModelController::fileFilter()
{
    return QString::fromStdString(fileDialogFilter(FormatUse::ReadModel,
                                                   tr("Structural models").toStdString(),
                                                   tr("All files").toStdString()));
}

bool OpenModelController::openFile(const QString &path)
{
    return start(path, QFileInfo(path).fileName());
}

bool OpenModelController::openSample()
{
    return start(QString(), tr("Sample model"));
}

bool OpenModelController::start(const QString &path, const QString &displayName)
{
    if (isBusy())
        return false;
    emit opening(displayName);
    std::shared_ptr<Progress> progress = begin();
    m_watcher.setFuture(QtConcurrent::run(&loadModel, path, displayName, std::move(progress)));
    return true;
}

void OpenModelController::onFinished()
{
    const QFuture<LoadResult> future = m_watcher.future();
    LoadResult result;
    if (future.resultCount() > 0)
        result = future.result();
    else
        result.error = {
            Message::Severity::Error, tr("Loading stopped without a result"), QString(), 0, {}};
    const RunStatus status = result.ok          ? RunStatus::Done
                             : result.cancelled ? RunStatus::Cancelled
                                                : RunStatus::Failed;
    end(status, result.error, [&] { emit loaded(result.loaded); });
}

} // namespace stratamesh
