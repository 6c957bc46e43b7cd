#include "remesh_controller.h"

#include "common/error.h"
#include "common/progress.h"
#include "error_message.h"
#include "model/model_counts.h"
#include "remesh/remesh_review.h"

#include <QElapsedTimer>
#include <QPromise>
#include <QtConcurrent>

#include <algorithm>

namespace stratamesh {

namespace {

// Runs in the worker thread: core work only, plus conversion into messages.
void runRemesh(QPromise<RemeshRun> &promise, std::shared_ptr<const Model> input,
               RemeshParams params, std::shared_ptr<Progress> progress)
{
    QElapsedTimer timer;
    timer.start();
    RemeshRun run;
    try {
        // The input's validity was shown when it was opened.
        RemeshReviewOptions options;
        options.checkInput = false;
        RemeshReview review = remeshAndReview(*input, params, options, *progress);
        if (progress->isCancelled() || promise.isCanceled())
            throw Cancelled();
        RemeshResult &result = review.result;
        RemeshOutcome &o = run.outcome;
        o.comparison = std::move(review.comparison);
        o.counts = countEntities(result.model);
        o.siteCount = result.siteCount;
        o.initialSiteCount = result.initialSiteCount;
        o.validity = result.validity;
        o.refinementRounds = result.refinementRounds;
        o.refinementRoundsRun = result.refinementRoundsRun;
        o.remainingTargets = result.remainingTargets;
        o.sizedSiteCount = result.sizedSiteCount;
        o.smallestCellSize = result.smallestCellSize;
        o.pocketsOpened = result.pocketsOpened;
        o.timings = result.timings;
        o.energy = result.energy;
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
    promise.addResult(std::move(run));
}

} // namespace

RemeshController::RemeshController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::RemeshOutcome>();
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
    std::shared_ptr<Progress> progress = begin(tr("Remeshing"));
    if (!progress)
        return false;
    ++m_runCount;
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
        run.error = {
            Message::Severity::Error, tr("Remeshing stopped without a result"), QString(), 0, {}};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
