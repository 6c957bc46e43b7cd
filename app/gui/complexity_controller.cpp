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

// The engine restarts its fraction at each stage; the bar moves forward through fixed spans:
// global measures 0–10 %, CVT 10–70 %, counting per cell 70–100 %.
int overallPercent(double fraction, const std::string &stage)
{
    const double f = std::clamp(fraction, 0.0, 1.0);
    if (stage.rfind("geometric", 0) == 0)
        return int(10 * f);
    if (stage.find("CVT") != std::string::npos)
        return 10 + int(60 * f);
    if (stage.find("counting") != std::string::npos)
        return 70 + int(30 * f);
    return -1; // unknown stage: keep the bar where it is
}

// Runs in the worker thread: core work only, plus conversion into messages.
void runComplexity(QPromise<ComplexityRun> &promise, std::shared_ptr<const Model> model,
                   ComplexityParams params, std::shared_ptr<Progress> cancel)
{
    QElapsedTimer timer;
    timer.start();
    ComplexityRun run;
    promise.setProgressRange(0, 100);
    const QString measuring = ComplexityController::tr("Measuring complexity");
    int percent = 0;
    Progress progress([&](double fraction, const std::string &stage) {
        if (cancel->isCancelled() || promise.isCanceled())
            throw Cancelled();
        percent = std::max(percent, overallPercent(fraction, stage));
        const QString text = stage.empty()
                                 ? measuring
                                 : measuring + QStringLiteral(": ") + QString::fromStdString(stage);
        promise.setProgressValueAndText(percent, text);
    });
    try {
        promise.setProgressValueAndText(0, measuring);
        auto report =
            std::make_shared<ComplexityReport>(computeComplexity(*model, params, progress));
        if (cancel->isCancelled())
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
    promise.setProgressValueAndText(100, QString());
    promise.addResult(std::move(run));
}

} // namespace

ComplexityController::ComplexityController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::ComplexityOutcome>();
    relayProgress(m_watcher);
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
    std::shared_ptr<Progress> progress = begin();
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
                     tr("The complexity analysis stopped without a result"), QString(), 0};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
