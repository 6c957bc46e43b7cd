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
                std::shared_ptr<Progress> cancel)
{
    QElapsedTimer timer;
    timer.start();
    TetmeshRun run;
    promise.setProgressRange(0, 100);
    const QString onInput = TetmeshController::tr("Tetrahedralising the input");
    const QString onRemesh = TetmeshController::tr("Tetrahedralising the remesh");
    // compareTetmeshes() runs the input over 0–50 % and the remesh over 50–100 %.
    Progress progress([&](double fraction, const std::string &stage) {
        if (cancel->isCancelled() || promise.isCanceled())
            throw Cancelled();
        const QString prefix = output && fraction >= 0.5 ? onRemesh : onInput;
        const QString text =
            stage.empty() ? prefix : prefix + QStringLiteral(": ") + QString::fromStdString(stage);
        promise.setProgressValueAndText(int(100 * std::clamp(fraction, 0.0, 1.0)), text);
    });
    try {
        promise.setProgressValueAndText(0, onInput);
        TetmeshOutcome &o = run.outcome;
        if (output) {
            TetmeshComparison c = compareTetmeshes(*input, *output, params, progress);
            o.inputSide = std::make_shared<const TetmeshSide>(std::move(c.input));
            o.outputSide = std::make_shared<const TetmeshSide>(std::move(c.output));
        } else {
            o.inputSide =
                std::make_shared<const TetmeshSide>(tetmeshModel(*input, params, progress));
        }
        if (cancel->isCancelled())
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
    promise.setProgressValueAndText(100, QString());
    promise.addResult(std::move(run));
}

} // namespace

TetmeshController::TetmeshController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::TetmeshOutcome>();
    relayProgress(m_watcher);
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
    std::shared_ptr<Progress> progress = begin();
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
        run.error = {Message::Severity::Error, tr("Tetrahedralisation stopped without a result"),
                     QString(), 0};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
