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
#include <QEventLoop>
#include <QFileInfo>
#include <QPromise>
#include <QtConcurrent>

namespace stratamesh {

namespace {

// Runs in the worker thread: everything here is core work, plus conversion into messages.
void loadModel(QPromise<LoadResult> &promise, const QString &path, const QString &displayName)
{
    QElapsedTimer timer;
    timer.start();
    LoadResult result;
    result.loaded.path = path;
    result.loaded.displayName = displayName;
    const std::string file = path.toStdString();
    promise.setProgressRange(0, 100);
    try {
        Model model;
        if (path.isEmpty()) {
            promise.setProgressValueAndText(5,
                                            OpenModelController::tr("Building the sample model"));
            model = sampleModel();
        } else {
            promise.setProgressValueAndText(5,
                                            OpenModelController::tr("Reading %1").arg(displayName));
            model = readModel(file);
        }
        promise.setProgressValueAndText(60,
                                        OpenModelController::tr("Recovering lines and corners"));
        model = recoverTopology(std::move(model));
        const QString checking = OpenModelController::tr("Checking validity");
        promise.setProgressValueAndText(85, checking);
        Progress progress([&](double fraction, const std::string &) {
            if (promise.isCanceled())
                throw Cancelled(); // the window is closing
            promise.setProgressValueAndText(85 + int(14 * fraction), checking);
        });
        ValidityReport report = checkValidity(model, progress);
        if (isRingMeshFile(file)) // a GeoModel also states its lines and corners
            addRingMeshTopologyProblems(file, model, report);
        result.loaded.messages = validityMessages(report, path);
        result.loaded.counts = countEntities(model);
        result.loaded.model = std::make_shared<const Model>(std::move(model));
        result.ok = true;
    } catch (const std::exception &e) {
        result.error = errorMessage(e, path);
    }
    result.loaded.milliseconds = timer.elapsed();
    promise.setProgressValueAndText(100, QString());
    promise.addResult(std::move(result));
}

} // namespace

OpenModelController::OpenModelController(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<stratamesh::Message>();
    qRegisterMetaType<stratamesh::LoadedModel>();
    connect(&m_watcher, &QFutureWatcher<LoadResult>::progressValueChanged, this,
            [this](int value) { emit progressChanged(value, m_watcher.progressText()); });
    connect(&m_watcher, &QFutureWatcher<LoadResult>::progressTextChanged, this,
            [this](const QString &text) { emit progressChanged(m_watcher.progressValue(), text); });
    connect(&m_watcher, &QFutureWatcher<LoadResult>::finished, this,
            &OpenModelController::onFinished);
}

OpenModelController::~OpenModelController()
{
    // The validity check stops at its next progress tick; the reader cannot be interrupted.
    m_watcher.disconnect(this);
    m_watcher.cancel();
    m_watcher.waitForFinished();
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

bool OpenModelController::isBusy() const
{
    return m_pending;
}

void OpenModelController::waitForFinished()
{
    if (!m_pending)
        return;
    // The watcher reports through queued events: spin an event loop until finished() went out.
    QEventLoop loop;
    connect(this, &OpenModelController::finished, &loop, &QEventLoop::quit);
    if (m_pending)
        loop.exec();
}

bool OpenModelController::start(const QString &path, const QString &displayName)
{
    if (isBusy())
        return false;
    m_pending = true;
    emit started(displayName);
    m_watcher.setFuture(QtConcurrent::run(&loadModel, path, displayName));
    return true;
}

void OpenModelController::onFinished()
{
    m_pending = false;
    const QFuture<LoadResult> future = m_watcher.future();
    LoadResult result;
    if (future.resultCount() > 0)
        result = future.result();
    else
        result.error = {Message::Severity::Error, tr("Loading stopped without a result"), QString(),
                        0};
    if (result.ok)
        emit loaded(result.loaded);
    else
        emit failed(result.error);
    emit finished(result.ok);
}

} // namespace stratamesh
