#include "remesh_controller.h"

#include "common/error.h"
#include "common/progress.h"
#include "error_message.h"
#include "model/model_counts.h"

#include <QElapsedTimer>
#include <QPromise>
#include <QtConcurrent>

#include <algorithm>

namespace stratamesh {

namespace {

// Runs in the worker thread: core work only, plus conversion into messages.
void runRemesh(QPromise<RemeshRun> &promise, std::shared_ptr<const Model> input,
               RemeshParams params, std::shared_ptr<Progress> cancel)
{
    QElapsedTimer timer;
    timer.start();
    RemeshRun run;
    promise.setProgressRange(0, 100);
    // The engine's stages, then the comparison: 0–85 % and 85–100 %.
    const auto relay = [&](int from, int span, const QString &prefix) {
        return Progress(
            [&promise, &cancel, from, span, prefix](double fraction, const std::string &stage) {
                if (cancel->isCancelled() || promise.isCanceled())
                    throw Cancelled();
                const QString text =
                    stage.empty() ? prefix
                                  : prefix + QStringLiteral(": ") + QString::fromStdString(stage);
                promise.setProgressValueAndText(from + int(span * std::clamp(fraction, 0.0, 1.0)),
                                                text);
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
        o.initialSiteCount = result.initialSiteCount;
        o.validity = result.validity;
        o.params = params;
        o.input = std::move(input);
        o.ledger = std::make_shared<const SimplificationLedger>(std::move(result.ledger));
        o.output = std::make_shared<const Model>(std::move(result.model));
        run.status = RemeshRun::Status::Done;
    } catch (const Cancelled &) {
        run.status = RemeshRun::Status::Cancelled;
    } catch (const std::exception &e) {
        run.error = errorMessage(e);
    }
    run.outcome.milliseconds = timer.elapsed();
    promise.setProgressValueAndText(100, QString());
    promise.addResult(std::move(run));
}

} // namespace

RemeshController::RemeshController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::RemeshOutcome>();
    relayProgress(m_watcher);
    connect(&m_watcher, &QFutureWatcher<RemeshRun>::finished, this, &RemeshController::onFinished);
}

RemeshController::~RemeshController()
{
    stop(m_watcher);
}

bool RemeshController::start(std::shared_ptr<const Model> input, const RemeshParams &params)
{
    if (!input)
        return false;
    std::shared_ptr<Progress> progress = begin();
    if (!progress)
        return false;
    m_watcher.setFuture(
        QtConcurrent::run(&runRemesh, std::move(input), params, std::move(progress)));
    return true;
}

void RemeshController::onFinished()
{
    const QFuture<RemeshRun> future = m_watcher.future();
    RemeshRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {Message::Severity::Error, tr("Remeshing stopped without a result"), QString(),
                     0};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
