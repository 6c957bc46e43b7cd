#include "hybrid_controller.h"

#include "common/error.h"
#include "common/progress.h"
#include "error_message.h"
#include "hybrid/cell_quality.h"

#include <QElapsedTimer>
#include <QPromise>
#include <QtConcurrent>

namespace stratamesh {

namespace {

// Runs in the worker thread: core work only, plus conversion into messages.
void runHybrid(QPromise<HybridRun> &promise, std::shared_ptr<const Model> model,
               HybridParams params, std::shared_ptr<Progress> progress)
{
    QElapsedTimer timer;
    timer.start();
    HybridRun run;
    try {
        auto result = std::make_shared<HybridResult>(buildHybridMesh(*model, params, *progress));
        if (progress->isCancelled() || promise.isCanceled())
            throw Cancelled();
        if (!result->mesh.hasCells())
            throw InputError(result->message.empty() ? std::string("no valid mesh could be made")
                                                     : result->message);
        // The view colours by each cell's min dihedral angle, as the core measures it.
        VolumeMesh &mesh = result->mesh;
        mesh.cellQuality.clear();
        mesh.cellQuality.reserve(mesh.cells.size());
        for (const Cell &cell : mesh.cells)
            mesh.cellQuality.push_back(cellDihedrals(mesh, cell).minDegrees);
        mesh.qualityName = "min_dihedral_deg";

        HybridOutcome &o = run.outcome;
        HybridStatistics &s = o.statistics;
        s.byType = qualityByType(mesh);
        s.valid = result->validity.valid();
        s.invalidFound = result->invalidFound;
        s.repaired = result->repaired;
        s.segmentDual = result->segmentDualKept;
        s.vertexDual = result->vertexDualKept;
        s.transitionPyramids = result->transitionPyramids;
        s.fillTets = result->fillTets;
        s.fellBackToTetgen = result->fellBackToTetgen;
        s.seconds = result->timings.totalSeconds;
        s.message = QString::fromStdString(result->message);
        o.result = std::move(result);
        o.input = std::move(model);
        o.params = params;
        run.status = HybridRun::Status::Done;
    } catch (const Cancelled &) {
        run.status = HybridRun::Status::Cancelled;
    } catch (const std::exception &e) {
        run.error = errorMessage(e);
    }
    run.outcome.milliseconds = timer.elapsed();
    promise.addResult(std::move(run));
}

} // namespace

HybridController::HybridController(QObject *parent) : WorkflowJob(parent)
{
    qRegisterMetaType<stratamesh::HybridOutcome>();
    connect(&m_watcher, &QFutureWatcher<HybridRun>::finished, this, &HybridController::onFinished);
}

HybridController::~HybridController()
{
    stop(m_watcher);
}

bool HybridController::start(std::shared_ptr<const Model> model, const HybridParams &params)
{
    if (!model)
        return false;
    std::shared_ptr<Progress> progress = begin(tr("Building the hybrid mesh"));
    if (!progress)
        return false;
    m_watcher.setFuture(
        QtConcurrent::run(&runHybrid, std::move(model), params, std::move(progress)));
    return true;
}

void HybridController::onFinished()
{
    const QFuture<HybridRun> future = m_watcher.future();
    HybridRun run;
    if (future.resultCount() > 0)
        run = future.result();
    else
        run.error = {Message::Severity::Error,
                     tr("The hybrid mesher stopped without a result"),
                     QString(),
                     0,
                     {}};
    end(run.status, run.error, [&] { emit succeeded(run.outcome); });
}

} // namespace stratamesh
