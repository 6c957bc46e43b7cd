#include "complexity_controller.h"

#include "common/error.h"
#include "common/progress.h"
#include "error_message.h"

#include <QElapsedTimer>
#include <QPromise>
#include <QtConcurrent>

#include <algorithm>

namespace stratamesh {

namespace {

// Runs in the worker thread: core work only, plus conversion into messages.
void runComplexity(QPromise<ComplexityRun> &promise, std::shared_ptr<const Model> model,
                   ComplexityParams params, std::shared_ptr<Progress> progress)
{
    QElapsedTimer timer;
    timer.start();
    ComplexityRun run;
    try {
        auto report =
            std::make_shared<ComplexityReport>(computeComplexity(*model, params, *progress));
        if (progress->isCancelled() || promise.isCanceled())
            throw Cancelled();
        ComplexityOutcome &o = run.outcome;
        o.cells =
            std::make_shared<const std::vector<ConvexPolyhedron>>(report->local.front().cvt.cells);
        o.report = std::move(report);
        o.model = std::move(model);
        o.params = params;
        run.status = ComplexityRun::Status::Done;
    } catch (const Cancelled &) {
        run.status = ComplexityRun::Status::Cancelled;
    } catch (const std::exception &e) {
        run.error = errorMessage(e);
    }
    run.outcome.milliseconds = timer.elapsed();
    promise.addResult(std::move(run));
}

} // namespace

ComplexityController::ComplexityController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::ComplexityOutcome>();
    connect(&m_watcher, &QFutureWatcher<ComplexityRun>::finished, this,
            &ComplexityController::onFinished);
}

ComplexityController::~ComplexityController()
{
    stop(m_watcher);
}

bool ComplexityController::start(std::shared_ptr<const Model> model, const ComplexityParams &params)
{
    if (!model || params.cells.size() != 1)
        return false;
    std::shared_ptr<Progress> progress = begin(tr("Measuring complexity"));
    if (!progress)
        return false;
    m_watcher.setFuture(
        QtConcurrent::run(&runComplexity, std::move(model), params, std::move(progress)));
    return true;
}

void ComplexityController::onFinished()
{
    const QFuture<ComplexityRun> future = m_watcher.future();
    ComplexityRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {Message::Severity::Error,
                     tr("The complexity analysis stopped without a result"),
                     QString(),
                     0,
                     {}};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
