#include "tetmesh_controller.h"

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
void runTetmesh(QPromise<TetmeshRun> &promise, std::shared_ptr<const Model> input,
                std::shared_ptr<const Model> output, TetgenParams params,
                std::shared_ptr<Progress> progress)
{
    QElapsedTimer timer;
    timer.start();
    TetmeshRun run;
    try {
        TetmeshOutcome &o = run.outcome;
        if (output) {
            // compareTetmeshes() names its two sides' stages.
            TetmeshComparison c = compareTetmeshes(*input, *output, params, *progress);
            o.inputSide = std::make_shared<const TetmeshSide>(std::move(c.input));
            o.outputSide = std::make_shared<const TetmeshSide>(std::move(c.output));
        } else {
            o.inputSide =
                std::make_shared<const TetmeshSide>(tetmeshModel(*input, params, *progress));
        }
        if (progress->isCancelled() || promise.isCanceled())
            throw Cancelled();
        o.input = std::move(input);
        o.output = std::move(output);
        o.params = params;
        run.status = TetmeshRun::Status::Done;
    } catch (const Cancelled &) {
        run.status = TetmeshRun::Status::Cancelled;
    } catch (const std::exception &e) {
        run.error = errorMessage(e);
    }
    run.outcome.milliseconds = timer.elapsed();
    promise.addResult(std::move(run));
}

} // namespace

TetmeshController::TetmeshController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::TetmeshOutcome>();
    connect(&m_watcher, &QFutureWatcher<TetmeshRun>::finished, this,
            &TetmeshController::onFinished);
}

TetmeshController::~TetmeshController()
{
    stop(m_watcher);
}

bool TetmeshController::start(std::shared_ptr<const Model> input,
                              std::shared_ptr<const Model> output, const TetgenParams &params)
{
    if (!input)
        return false;
    std::shared_ptr<Progress> progress =
        begin(output ? tr("Tetrahedralising the input and the remesh")
                     : tr("Tetrahedralising the input"));
    if (!progress)
        return false;
    m_watcher.setFuture(QtConcurrent::run(&runTetmesh, std::move(input), std::move(output), params,
                                          std::move(progress)));
    return true;
}

void TetmeshController::onFinished()
{
    const QFuture<TetmeshRun> future = m_watcher.future();
    TetmeshRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {Message::Severity::Error,
                     tr("Tetrahedralisation stopped without a result"),
                     QString(),
                     0,
                     {}};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
