#include "remesh_workflow.h"

#include "comparison_table.h"
#include "disabled_reason.h"
#include "error_message.h"
#include "ledger_panel.h"
#include "model_scene.h"
#include "position_marker.h"
#include "remesh_controller.h"
#include "remesh_dialog.h"
#include "review_command.h"
#include "review_csv.h"
#include "review_panel.h"
#include "validity_messages.h"
#include "view_pair.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include "io/formats.h"
#include "io/mesh_writer.h"
#include "io/output_plan.h"
#include "remesh/surface_remesher.h"
#include "remesh/topology_refinement.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLayout>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QStyle>
#include <QUndoStack>

#include <vtkRenderer.h>

#include <algorithm>

namespace stratamesh {

RemeshWorkflow::RemeshWorkflow(Workbench &bench, QObject *parent)
    : Workflow(bench, parent), m_controller(new RemeshController(this)),
      m_review(new ReviewPanel(bench.window())), m_ledgerDock(new QDockWidget(bench.window())),
      m_comparison(new ComparisonTable(bench.window())),
      m_comparisonDock(new QDockWidget(bench.window())), m_remesh(new QAction(this)),
      m_cancel(new QAction(this)), m_save(new QAction(this)), m_exportReview(new QAction(this))
{
    const QStyle *style = bench.window()->style();
    m_remesh->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_remesh->setIcon(QIcon::fromTheme(QStringLiteral("system-run"),
                                       style->standardIcon(QStyle::SP_BrowserReload)));
    m_remesh->setEnabled(false);
    connect(m_remesh, &QAction::triggered, this, &RemeshWorkflow::remesh);
    m_cancel->setIcon(style->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QAction::triggered, this, &RemeshWorkflow::cancel);
    m_save->setShortcut(QKeySequence::SaveAs);
    m_save->setIcon(QIcon::fromTheme(QStringLiteral("document-save-as"),
                                     style->standardIcon(QStyle::SP_DialogSaveButton)));
    m_save->setEnabled(false);
    connect(m_save, &QAction::triggered, this, &RemeshWorkflow::chooseFile);
    m_exportReview->setIcon(style->standardIcon(QStyle::SP_DialogSaveButton));
    m_exportReview->setEnabled(false);
    connect(m_exportReview, &QAction::triggered, this, &RemeshWorkflow::chooseReviewFile);
    setDisabledReason(m_remesh, [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    });
    setDisabledReason(m_save, [this] {
        return !m_outcome ? tr("no remeshed model yet") : tr("another step is running");
    });
    setDisabledReason(m_exportReview, [] { return tr("no remeshed model yet"); });
    setDisabledReason(m_cancel, [] { return tr("no remesh is running"); });

    m_ledgerDock->setObjectName(QStringLiteral("ReviewDock"));
    m_ledgerDock->setWidget(m_review);
    m_review->addAction(m_exportReview);
    m_comparisonDock->setObjectName(QStringLiteral("ComparisonDock"));
    m_comparisonDock->setWidget(m_comparison);
    connect(m_review, &ReviewPanel::recordSelected, this, &RemeshWorkflow::showLedgerRecord);
    connect(m_review, &ReviewPanel::decisionRequested, this, &RemeshWorkflow::review);
    // However the decisions change (a choice, an undo, a project loaded), the table follows.
    connect(this, &RemeshWorkflow::decisionsChanged, this,
            [this] { m_review->setDecisions(m_decisions); });

    connect(m_controller, &RemeshController::started, this, &RemeshWorkflow::onStarted);
    connect(m_controller, &RemeshController::succeeded, this, &RemeshWorkflow::onRemeshed);
    connect(m_controller, &RemeshController::failed, this, &RemeshWorkflow::onFailed);
    connect(m_controller, &RemeshController::cancelled, this, &RemeshWorkflow::onCancelled);
    relay(m_controller);
}

RemeshWorkflow::~RemeshWorkflow()
{
    m_controller->disconnect(this);
    delete m_controller;
}

QList<QAction *> RemeshWorkflow::menuActions(Menu menu) const
{
    switch (menu) {
    case Menu::File:
        return {m_save, m_exportReview};
    case Menu::Mesh:
        return {m_remesh, m_cancel};
    case Menu::Edit:
    case Menu::View:
    case Menu::Analyse:
        break;
    }
    return {};
}

QList<QAction *> RemeshWorkflow::toolBarActions() const
{
    return {m_remesh};
}

QList<Workflow::Dock> RemeshWorkflow::docks() const
{
    return {{m_ledgerDock, DockPlace::WithMessages}, {m_comparisonDock, DockPlace::Review}};
}

WorkflowJob *RemeshWorkflow::job() const
{
    return m_controller;
}

void RemeshWorkflow::retranslate()
{
    m_remesh->setText(tr("&Remesh…"));
    m_remesh->setStatusTip(
        tr("Remesh all the surfaces at a chosen resolution, keeping the model conformal"));
    m_cancel->setText(tr("&Cancel Remeshing"));
    m_cancel->setStatusTip(tr("Stop the remeshing; the input model is left as it is"));
    m_save->setText(tr("Save Remeshed Model &As…"));
    m_save->setStatusTip(tr("Write the remeshed model as a Gocad, RINGMesh, Gmsh or VTK file"));
    m_exportReview->setText(tr("Export Re&view as CSV…"));
    m_exportReview->setToolTip(tr("Export Review as CSV: every record with its decision and note"));
    m_exportReview->setStatusTip(
        tr("Write every simplification with its decision and note as a CSV table"));
    m_ledgerDock->setWindowTitle(tr("Review"));
    m_ledgerDock->toggleViewAction()->setText(tr("&Review"));
    m_comparisonDock->setWindowTitle(tr("Quality"));
    m_comparisonDock->toggleViewAction()->setText(tr("&Quality"));
    updateViewTitles();
}

void RemeshWorkflow::setDecisions(const ReviewDecisions &decisions)
{
    if (decisions == m_decisions)
        return;
    m_decisions = decisions;
    emit decisionsChanged();
}

void RemeshWorkflow::clear()
{
    m_outcome.reset();
    setDecisions({});
    m_bench.hidePosition();
    m_bench.outputScene()->setModel(nullptr);
    m_review->setLedger(nullptr);
    m_comparison->setComparison(std::nullopt);
    m_bench.views()->setOutputShown(false);
    m_ledgerDock->hide();
    m_comparisonDock->hide();
    m_save->setEnabled(false);
    m_exportReview->setEnabled(false);
    updateViewTitles();
}

void RemeshWorkflow::enableActions(bool busy)
{
    m_remesh->setEnabled(!busy && m_bench.model());
    m_save->setEnabled(!busy && m_outcome.has_value());
    m_exportReview->setEnabled(m_outcome.has_value());
}

void RemeshWorkflow::remesh()
{
    if (!m_bench.model() || m_bench.isBusy())
        return;
    RemeshDialog dialog(m_bench.inputScene()->diagonal(), m_bench.window());
    dialog.setModelArea(modelArea(*m_bench.model()));
    if (m_lastParams.sites > 0 || m_lastParams.edgeLength > 0.0)
        dialog.setParams(m_lastParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    start(dialog.params());
}

bool RemeshWorkflow::start(const RemeshParams &params)
{
    if (m_bench.isBusy())
        return false;
    m_lastParams = params;
    return m_controller->start(m_bench.model(), params);
}

void RemeshWorkflow::onStarted()
{
    m_cancel->setEnabled(true);
    m_bench.setStatus(tr("Remeshing %1…").arg(m_bench.displayName()));
}

void RemeshWorkflow::show(const RemeshOutcome &outcome, const ReviewDecisions &decisions)
{
    emit outputReplaced();
    m_outcome = outcome;
    setDecisions(decisions);
    ModelScene *input = m_bench.inputScene();
    ModelScene *output = m_bench.outputScene();
    m_bench.hidePosition();
    output->setBoxVisible(input->boxVisible());
    output->setEdgesVisible(input->edgesVisible());
    output->setModel(outcome.output);
    m_bench.views()->setOutputShown(true);
    m_ledgerDock->show();
    m_ledgerDock->raise();
    m_comparisonDock->show();
    m_review->setLedger(outcome.ledger);
    m_exportReview->setEnabled(true);
    m_comparison->setComparison(outcome.comparison);
    m_save->setEnabled(!m_bench.isBusy());
    QMainWindow *window = m_bench.window();
    window->resizeDocks({m_comparisonDock}, {m_comparison->sizeHint().width()}, Qt::Horizontal);
    // Room for the buttons and a few rows to review.
    window->resizeDocks({m_ledgerDock}, {260}, Qt::Vertical);
    // Lay the new panes out now: the camera is framed for the views' final sizes.
    window->layout()->activate();
    m_bench.views()->splitEvenly();
    updateViewTitles();
    m_bench.resetCamera();
}

void RemeshWorkflow::onRemeshed(const RemeshOutcome &outcome)
{
    m_saved = false;
    m_cancel->setEnabled(false);
    show(outcome, {});
    emit runAdded(outcome);

    Message done;
    done.text = tr("Remeshed with %1 sites in %2 s: %3 triangles, %n simplification(s) recorded",
                   nullptr, int(outcome.ledger->size()))
                    .arg(QLocale().toString(outcome.siteCount),
                         QLocale().toString(outcome.milliseconds / 1000.0, 'f', 2),
                         QLocale().toString(qulonglong(outcome.output->triangleCount())));
    m_bench.addMessage(done);
    const int edits = countTopologyEdits(*outcome.ledger).total();
    if (edits > 0) {
        // Which features were not kept, without opening the Review: a warning when refinement
        // stopped at its caps with places still changed.
        const std::vector<std::string> names = topologyEditEntities(*outcome.ledger);
        QStringList shown;
        for (std::size_t i = 0; i < names.size() && i < 8; ++i)
            shown << QString::fromStdString(names[i]);
        if (names.size() > 8)
            shown << tr("… (%n in all)", nullptr, int(names.size()));
        const QString list = shown.join(QStringLiteral(", "));
        Message changed;
        if (outcome.remainingTargets > 0) {
            changed.severity = Message::Severity::Warning;
            changed.text = tr("%n topology change(s) left where refinement stopped (%1 of %2 "
                              "rounds, %3 sites), involving %4 — see Review",
                              nullptr, edits)
                               .arg(outcome.refinementRounds)
                               .arg(outcome.params.refinementRounds)
                               .arg(QLocale().toString(outcome.siteCount), list);
        } else {
            changed.text =
                tr("%n topology change(s), involving %1 — see Review", nullptr, edits).arg(list);
        }
        m_bench.addMessage(changed);
    }
    if (!outcome.validity.valid) {
        // Never announced as a plain success: a volume mesher would fail on it.
        Message invalid;
        invalid.severity = Message::Severity::Warning;
        invalid.text = tr(
            "The remeshed model is NOT valid: %n problem(s) left after local refinement; saving it "
            "is at your own risk",
            nullptr, int(outcome.validity.problems.size()));
        m_bench.addMessage(invalid);
        for (const Message &m : validityMessages(outcome.validity, QString()))
            m_bench.addMessage(m);
        m_bench.showMessages();
        m_bench.setStatus(tr("Remeshed, NOT valid: %n problem(s) — see Messages", nullptr,
                             int(outcome.validity.problems.size())));
        return;
    }
    m_bench.setStatus(
        tr("Remeshed: %n simplification(s) — see Review", nullptr, int(outcome.ledger->size())));
}

void RemeshWorkflow::onFailed(const Message &error)
{
    reportFailure(error, tr("Remeshing failed: %1").arg(error.text),
                  tr("Remeshing failed — see Messages"));
}

void RemeshWorkflow::onCancelled()
{
    reportCancel(tr("Remeshing cancelled: the previous result, if any, is kept"),
                 tr("Remeshing cancelled"));
}

void RemeshWorkflow::updateViewTitles()
{
    const QString input = tr("Input: %1").arg(m_bench.displayName());
    if (!m_outcome) {
        m_bench.views()->setTitles(input, QString());
        return;
    }
    const QLocale locale;
    m_bench.views()->setTitles(
        input, tr("Output: %1 sites, %2 triangles")
                   .arg(locale.toString(m_outcome->siteCount),
                        locale.toString(qulonglong(m_outcome->output->triangleCount()))));
}

LedgerPanel *RemeshWorkflow::ledgerPanel() const
{
    return m_review->ledgerPanel();
}

PositionMarker *RemeshWorkflow::marker() const
{
    return m_bench.outputMarker();
}

void RemeshWorkflow::showLedgerRecord(int recordIndex)
{
    const LedgerRecord *record =
        m_outcome && recordIndex >= 0 && recordIndex < int(m_outcome->ledger->size())
            ? &(*m_outcome->ledger)[std::size_t(recordIndex)]
            : nullptr;
    if (!record) {
        m_bench.hidePosition();
        return;
    }
    // A distance or a length hints at how large the change is; an area is no radius.
    const bool isLength = record->sizeMeaning == "distance" || record->sizeMeaning == "length";
    m_bench.showPosition(record->position, isLength ? 0.5 * record->size : 0.0);
}

void RemeshWorkflow::review(int record, const ReviewDecision &decision)
{
    if (!m_outcome || record < 0 || record >= int(m_outcome->ledger->size()))
        return;
    const ReviewDecision before = m_decisions.decision(record);
    if (before == decision)
        return;
    m_bench.undoStack()->push(new ReviewCommand(*this, record, before, decision));
}

bool RemeshWorkflow::chooseReviewFile()
{
    if (!m_outcome)
        return false;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    QString path = QFileDialog::getSaveFileName(m_bench.window(), tr("Export Review"), dir,
                                                tr("CSV table (*.csv)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".csv");
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    return exportReview(path);
}

bool RemeshWorkflow::exportReview(const QString &path)
{
    if (!m_outcome)
        return false;
    Message message;
    message.file = path;
    try {
        writeReviewCsv(path, *m_outcome->ledger, m_decisions);
        message.text = tr("Review exported: %1 of %2 records reviewed")
                           .arg(QLocale().toString(m_decisions.reviewedCount()),
                                QLocale().toString(qulonglong(m_outcome->ledger->size())));
        m_bench.addMessage(message);
        m_bench.setStatus(tr("Exported %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_bench.addMessage(message);
    m_bench.showMessages();
    m_bench.setStatus(tr("Could not export the review"));
    return false;
}

QString RemeshWorkflow::unsavedWork() const
{
    return m_outcome && !m_saved ? tr("The remeshed model has not been saved.") : QString();
}

bool RemeshWorkflow::saveUnsavedWork()
{
    return chooseFile();
}

bool RemeshWorkflow::chooseFile()
{
    if (!m_outcome)
        return false;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    QString selected;
    QString path = QFileDialog::getSaveFileName(
        m_bench.window(), tr("Save Remeshed Model"), dir,
        QString::fromStdString(fileDialogFilter(FormatUse::WriteModel, {}, {})), &selected);
    if (path.isEmpty())
        return false;
    path = QString::fromStdString(
        withFormatExtension(path.toStdString(), FormatUse::WriteModel, selected.toStdString()));
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    return save(path);
}

bool RemeshWorkflow::save(const QString &path)
{
    if (!m_outcome)
        return false;
    Message message;
    message.file = path;
    try {
        // As the command line does (io/output_plan.h): never over the open model, checked before
        // writing, through a temporary file (which keeps the extension) and a rename.
        OutputPlan plan({m_bench.modelPath().toStdString()});
        plan.add(path.toStdString(), "remeshed model");
        plan.write(path.toStdString(), [&](const std::string &temporary) {
            exportModel(*m_outcome->output, temporary);
        });
        plan.commit();
        m_saved = true;
        message.text = tr("Remeshed model saved");
        m_bench.addMessage(message);
        m_bench.setStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_bench.addMessage(message);
    m_bench.showMessages();
    m_bench.setStatus(tr("Could not save the remeshed model"));
    return false;
}

} // namespace stratamesh
