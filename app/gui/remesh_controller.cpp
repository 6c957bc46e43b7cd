#include "remesh_controller.h"

#include "common/error.h"
#include "common/progress.h"
#include "model/model_counts.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QPromise>
#include <QtConcurrent>

#include <algorithm>

namespace stratamesh {

namespace {

// Runs in the worker thread: core work only, plus conversion into messages.
void runRemesh(QPromise<RemeshRun> &promise, std::shared_ptr<const Model> input, RemeshParams params,
               std::shared_ptr<Progress> cancel)
{
    QElapsedTimer timer;
    timer.start();
    RemeshRun run;
    promise.setProgressRange(0, 100);
    // The engine's stages, then the comparison: 0–85 % and 85–100 %.
    const auto relay = [&](int from, int span, const QString &prefix) {
        return Progress([&promise, &cancel, from, span, prefix](double fraction, const std::string &stage) {
            if (cancel->isCancelled() || promise.isCanceled())
                throw Cancelled();
            const QString text = stage.empty() ? prefix : prefix + QStringLiteral(": ") + QString::fromStdString(stage);
            promise.setProgressValueAndText(from + int(span * std::clamp(fraction, 0.0, 1.0)), text);
        });
    };
    try {
        const QString remeshing = RemeshController::tr("Remeshing");
        promise.setProgressValueAndText(0, remeshing);
        Progress remeshProgress = relay(0, 85, remeshing);
        RemeshResult result = remeshModel(*input, params, remeshProgress);
        if (cancel->isCancelled())
            throw Cancelled();
        const QString comparing = RemeshController::tr("Comparing with the input");
        promise.setProgressValueAndText(85, comparing);
        Progress compareProgress = relay(85, 15, comparing);
        HausdorffParams hausdorff;
        hausdorff.samplesPerSide = RemeshController::kHausdorffSamples;
        RemeshOutcome &o = run.outcome;
        o.comparison = compareModels(*input, result.model, hausdorff, compareProgress);
        o.comparison.output.resolution = std::to_string(result.siteCount);
        o.comparison.output.samplingSeconds = result.timings.samplingSeconds;
        o.comparison.output.meshSeconds = result.timings.meshSeconds;
        o.counts = countEntities(result.model);
        o.siteCount = result.siteCount;
        o.params = params;
        o.input = std::move(input);
        o.ledger = std::make_shared<const SimplificationLedger>(std::move(result.ledger));
        o.output = std::make_shared<const Model>(std::move(result.model));
        run.status = RemeshRun::Status::Done;
    } catch (const Cancelled &) {
        run.status = RemeshRun::Status::Cancelled;
    } catch (const FileError &e) {
        run.error = {Message::Severity::Error, QString::fromStdString(e.cause()), QString::fromStdString(e.file()),
                     e.line()};
    } catch (const std::exception &e) {
        run.error = {Message::Severity::Error, QString::fromStdString(e.what()), QString(), 0};
    }
    run.outcome.milliseconds = timer.elapsed();
    promise.setProgressValueAndText(100, QString());
    promise.addResult(std::move(run));
}

} // namespace

RemeshController::RemeshController(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<stratamesh::Message>();
    qRegisterMetaType<stratamesh::RemeshOutcome>();
    // The watcher's value and text signals arrive separately, and the value read with a text may
    // be ahead of a value signal still queued: the worker only moves forward, so the bar does too.
    connect(&m_watcher, &QFutureWatcher<RemeshRun>::progressValueChanged, this, [this](int value) {
        m_percent = std::max(m_percent, value);
        emit progressChanged(m_percent, m_watcher.progressText());
    });
    connect(&m_watcher, &QFutureWatcher<RemeshRun>::progressTextChanged, this, [this](const QString &text) {
        m_percent = std::max(m_percent, m_watcher.progressValue());
        emit progressChanged(m_percent, text);
    });
    connect(&m_watcher, &QFutureWatcher<RemeshRun>::finished, this, &RemeshController::onFinished);
}

RemeshController::~RemeshController()
{
    m_watcher.disconnect(this);
    if (m_progress)
        m_progress->cancel();
    m_watcher.cancel();
    m_watcher.waitForFinished();
}

bool RemeshController::start(std::shared_ptr<const Model> input, const RemeshParams &params)
{
    if (m_pending || !input)
        return false;
    m_pending = true;
    m_percent = 0;
    m_progress = std::make_shared<Progress>();
    emit started();
    m_watcher.setFuture(QtConcurrent::run(&runRemesh, std::move(input), params, m_progress));
    return true;
}

void RemeshController::cancel()
{
    if (m_pending && m_progress)
        m_progress->cancel();
}

void RemeshController::waitForFinished()
{
    if (!m_pending)
        return;
    QEventLoop loop;
    connect(this, &RemeshController::finished, &loop, &QEventLoop::quit);
    if (m_pending)
        loop.exec();
}

void RemeshController::onFinished()
{
    m_pending = false;
    m_progress.reset();
    const QFuture<RemeshRun> future = m_watcher.future();
    RemeshRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {Message::Severity::Error, tr("Remeshing stopped without a result"), QString(), 0};
    switch (run.status) {
    case RemeshRun::Status::Done: emit succeeded(run.outcome); break;
    case RemeshRun::Status::Cancelled: emit cancelled(); break;
    case RemeshRun::Status::Failed: emit failed(run.error); break;
    }
    emit finished(run.status == RemeshRun::Status::Done);
}

} // namespace stratamesh
