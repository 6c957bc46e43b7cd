#include "project_workflow.h"

#include "exaggeration_workflow.h"

#include "app_settings.h"
#include "comparison_table.h"
#include "disabled_reason.h"
#include "error_message.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "open_workflow.h"
#include "project_file.h"
#include "project_runs.h"
#include "remesh_report.h"
#include "remesh_workflow.h"
#include "restored_outcome.h"
#include "runs_panel.h"
#include "view_pair.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include "common/error.h"
#include "quality/model_comparison.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonArray>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QUndoCommand>
#include <QUndoStack>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace stratamesh {

namespace {

// What the two views show: a run, or the input model (-1), in the input view; a run in the output.
struct ViewRuns {
    int input;
    int output;
};

// Edit > Undo after choosing a run, or two runs to compare, shows what was shown before.
class ShowRunCommand : public QUndoCommand {
public:
    ShowRunCommand(ProjectWorkflow &workflow, ViewRuns from, ViewRuns to, const QString &text)
        : QUndoCommand(text), m_workflow(workflow), m_from(from), m_to(to)
    {
    }
    void redo() override { m_workflow.showRuns(m_to.input, m_to.output); }
    void undo() override { m_workflow.showRuns(m_from.input, m_from.output); }

private:
    ProjectWorkflow &m_workflow;
    ViewRuns m_from;
    ViewRuns m_to;
};

QString describeParams(const RemeshParams &p)
{
    const QLocale locale;
    QString text = p.edgeLength > 0.0
                       ? ProjectWorkflow::tr("edge %1").arg(locale.toString(p.edgeLength, 'g', 4))
                       : ProjectWorkflow::tr("%1 sites").arg(locale.toString(p.sites));
    text += ProjectWorkflow::tr(", %n iteration(s)", nullptr, p.iterations);
    if (p.dResolution > 0.0)
        text +=
            ProjectWorkflow::tr(", d_resolution %1").arg(locale.toString(p.dResolution, 'g', 4));
    if (p.adaptive)
        text += ProjectWorkflow::tr(", adaptive");
    return text;
}

QJsonArray triple(const double v[3])
{
    return QJsonArray{v[0], v[1], v[2]};
}

bool readTriple(const QJsonValue &value, double v[3])
{
    const QJsonArray a = value.toArray();
    if (a.size() != 3)
        return false;
    for (int i = 0; i < 3; ++i)
        v[i] = a[i].toDouble();
    return true;
}

// The shared camera of both views, so that a reopened project looks where it was left.
QJsonObject cameraJson(vtkCamera *camera)
{
    double position[3], focal[3], up[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    return QJsonObject{{QStringLiteral("position"), triple(position)},
                       {QStringLiteral("focal_point"), triple(focal)},
                       {QStringLiteral("view_up"), triple(up)},
                       {QStringLiteral("view_angle"), camera->GetViewAngle()}};
}

void applyCamera(const QJsonObject &json, vtkCamera *camera)
{
    double position[3], focal[3], up[3];
    if (!readTriple(json.value(QLatin1String("position")), position)
        || !readTriple(json.value(QLatin1String("focal_point")), focal)
        || !readTriple(json.value(QLatin1String("view_up")), up))
        return; // no camera saved: the views keep the framing of the whole model
    camera->SetPosition(position);
    camera->SetFocalPoint(focal);
    camera->SetViewUp(up);
    camera->SetViewAngle(json.value(QLatin1String("view_angle")).toDouble(30.0));
}

RemeshReportFacts factsOf(const RemeshOutcome &o)
{
    return {o.initialSiteCount, o.siteCount,    o.refinementRounds, o.refinementRoundsRun,
            o.remainingTargets, o.timings,      o.energy,           o.sizedSiteCount,
            o.smallestCellSize, o.pocketsOpened};
}

} // namespace

struct ProjectWorkflow::Pending {
    QString path;
    ProjectFile file;
    std::vector<RunRead> runs;
    bool relocated = false; // the input was found elsewhere: the project must be saved again
};

ProjectWorkflow::ProjectWorkflow(Workbench &bench, OpenWorkflow &open, RemeshWorkflow &remesh,
                                 QObject *parent)
    : Workflow(bench, parent), m_openWorkflow(open), m_remesh(remesh),
      m_panel(new RunsPanel(bench.window())), m_dock(new QDockWidget(bench.window())),
      m_open(new QAction(this)), m_save(new QAction(this)), m_saveAs(new QAction(this))
{
    m_dock->setObjectName(QStringLiteral("RunsDock"));
    m_dock->setWidget(m_panel);
    m_save->setShortcut(QKeySequence::Save);
    m_saveAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    m_save->setEnabled(false);
    m_saveAs->setEnabled(false);
    connect(m_open, &QAction::triggered, this, &ProjectWorkflow::chooseProject);
    connect(m_save, &QAction::triggered, this, &ProjectWorkflow::save);
    connect(m_saveAs, &QAction::triggered, this, &ProjectWorkflow::saveAs);
    for (QAction *action : {m_save, m_saveAs})
        setDisabledReason(action, [this] {
            return !m_bench.model() ? tr("no model open") : tr("another step is running");
        });
    setDisabledReason(m_open, [] { return tr("another step is running"); });
    connect(m_panel, &RunsPanel::runChosen, this, &ProjectWorkflow::chooseRun);
    connect(m_panel, &RunsPanel::compareChosen, this, &ProjectWorkflow::compareRuns);
    connect(m_panel, &RunsPanel::inputChosen, this, &ProjectWorkflow::chooseInput);
    connect(&remesh, &RemeshWorkflow::runAdded, this, &ProjectWorkflow::onRunAdded);
    connect(&remesh, &RemeshWorkflow::decisionsChanged, this, &ProjectWorkflow::onDecisionsChanged);
    // Workflow::finished comes once the window shows the model (MainWindow::showModel has run).
    connect(&open, &Workflow::finished, this, &ProjectWorkflow::onOpenFinished);
    m_locate = [this](const QString &missing) {
        return QFileDialog::getOpenFileName(
            m_bench.window(), tr("Locate the Input Model %1").arg(QFileInfo(missing).fileName()),
            QFileInfo(missing).absolutePath(), OpenModelController::fileFilter());
    };
}

ProjectWorkflow::~ProjectWorkflow() = default;

QList<QAction *> ProjectWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::File)
        return {m_open, m_save, m_saveAs};
    return {};
}

QList<Workflow::Dock> ProjectWorkflow::docks() const
{
    return {{m_dock, DockPlace::WithMessages}};
}

void ProjectWorkflow::retranslate()
{
    m_open->setText(tr("Open &Project…"));
    m_open->setStatusTip(tr("Open a StrataMesh project: its model, remesh runs and reviews"));
    m_save->setText(tr("&Save Project"));
    m_save->setStatusTip(tr("Save the remesh runs, their results and reviews as a project"));
    m_saveAs->setText(tr("Save Project As…"));
    m_saveAs->setStatusTip(tr("Save the project under another name"));
    m_dock->setWindowTitle(tr("Runs"));
    m_dock->toggleViewAction()->setText(tr("R&uns"));
    m_panel->retranslate();
    updatePanel();
    updateViewTitles(); // after RemeshWorkflow's, which name the input model
}

void ProjectWorkflow::clear()
{
    m_runs.clear();
    m_shown = -1;
    m_compared = -1; // the Workbench puts the next model in the input view
    m_remesh.comparisonTable()->setColumnNames({}, {});
    m_path.clear();
    emit pathChanged(m_path);
    setModified(false);
    updatePanel();
    m_dock->hide();
    m_save->setEnabled(false);
    m_saveAs->setEnabled(false);
}

void ProjectWorkflow::enableActions(bool busy)
{
    m_open->setEnabled(!busy);
    m_save->setEnabled(!busy && m_bench.model());
    m_saveAs->setEnabled(!busy && m_bench.model());
}

QString ProjectWorkflow::unsavedWork() const
{
    return m_modified ? tr("The project's runs and reviews have not been saved.") : QString();
}

bool ProjectWorkflow::saveUnsavedWork()
{
    return save();
}

void ProjectWorkflow::setModified(bool modified)
{
    m_modified = modified;
    m_bench.window()->setWindowModified(modified);
}

void ProjectWorkflow::onRunAdded(const RemeshOutcome &outcome)
{
    int id = 1;
    for (const Run &run : m_runs)
        id = std::max(id, run.id + 1);
    m_runs.push_back({outcome, {}, {}, {}, id, runFolderName(id)});
    m_shown = int(m_runs.size()) - 1;
    setInputRun(-1); // a new run is seen against the input it was made from
    setModified(true);
    updatePanel();
    m_dock->show();
}

void ProjectWorkflow::onDecisionsChanged()
{
    // While a run is being shown, or before a new run joins the list, the decisions belong to it.
    const auto &shown = m_remesh.outcome();
    if (m_applying || m_shown < 0 || !shown
        || shown->output != m_runs[std::size_t(m_shown)].outcome.output)
        return;
    m_runs[std::size_t(m_shown)].decisions = m_remesh.decisions();
    setModified(true);
    updatePanel();
}

// A row chosen in the table goes to the output view, beside the input model.
void ProjectWorkflow::chooseRun(int index)
{
    if (index < 0 || index >= int(m_runs.size()) || (index == m_shown && m_compared < 0)
        || m_bench.isBusy()) {
        updatePanel(); // the selection goes back to the run shown
        return;
    }
    m_bench.undoStack()->push(
        new ShowRunCommand(*this, {m_compared, m_shown}, {-1, index},
                           tr("Show Run %1").arg(m_runs[std::size_t(index)].id)));
}

bool ProjectWorkflow::compareRuns(int first, int second)
{
    const int count = int(m_runs.size());
    if (first < 0 || first >= count || second < 0 || second >= count || first == second
        || m_bench.isBusy())
        return false;
    if (first == m_compared && second == m_shown)
        return true;
    m_bench.undoStack()->push(new ShowRunCommand(*this, {m_compared, m_shown}, {first, second},
                                                 tr("Compare Runs %1 and %2")
                                                     .arg(m_runs[std::size_t(first)].id)
                                                     .arg(m_runs[std::size_t(second)].id)));
    return true;
}

void ProjectWorkflow::chooseInput()
{
    if (m_compared < 0 || m_bench.isBusy())
        return;
    m_bench.undoStack()->push(new ShowRunCommand(*this, {m_compared, m_shown}, {-1, m_shown},
                                                 tr("Show Input vs Output")));
}

void ProjectWorkflow::showRuns(int input, int output)
{
    if (output != m_shown)
        showRun(output);
    setInputRun(input);
    updateViewTitles(); // showRun named the input model
    updateComparison();
    updatePanel();
    if (input >= 0)
        m_bench.setStatus(tr("Comparing run %1 with run %2")
                              .arg(m_runs[std::size_t(input)].id)
                              .arg(m_runs[std::size_t(output)].id));
}

// The Workbench's model stays the input: remeshing, the model's tree and saving still work on it;
// only what the input view draws changes.
void ProjectWorkflow::setInputRun(int index)
{
    if (index >= int(m_runs.size()))
        index = -1;
    if (index == m_compared)
        return;
    m_compared = index;
    ModelScene *scene = m_bench.inputScene();
    scene->setModel(index < 0 ? m_bench.model() : m_runs[std::size_t(index)].outcome.output);
    m_bench.hidePosition();
    m_bench.updateLegend();
    updateViewTitles();
    updateComparison();
    m_bench.render();
}

// Input vs Output compares what the views show: the run with its input, or two runs (figures of
// both as measured when they were made; nothing is measured again).
void ProjectWorkflow::updateComparison()
{
    ComparisonTable *table = m_remesh.comparisonTable();
    if (m_shown < 0 || m_shown >= int(m_runs.size())) {
        table->setColumnNames({}, {});
        return;
    }
    const Run &shown = m_runs[std::size_t(m_shown)];
    if (m_compared < 0) {
        table->setColumnNames({}, {});
        table->setComparison(shown.outcome.comparison);
        return;
    }
    const Run &compared = m_runs[std::size_t(m_compared)];
    table->setColumnNames(tr("Run %1").arg(compared.id), tr("Run %1").arg(shown.id));
    try {
        table->setComparison(
            stratamesh::compareRuns(compared.outcome.comparison, shown.outcome.comparison));
    } catch (const InputError &e) {
        table->setComparison(std::nullopt);
        m_bench.setStatus(QString::fromStdString(e.what()));
    }
}

// While comparing, each view names its run; else RemeshWorkflow's titles (Input: …, Output: …).
void ProjectWorkflow::updateViewTitles()
{
    if (m_compared < 0 || m_shown < 0) {
        m_remesh.updateViewTitles();
        return;
    }
    const QLocale locale;
    const auto title = [&](int index) {
        const Run &run = m_runs[std::size_t(index)];
        return tr("Run %1: %2 sites, %3 triangles")
            .arg(run.id)
            .arg(locale.toString(run.outcome.siteCount),
                 locale.toString(qulonglong(run.outcome.output->triangleCount())));
    };
    m_bench.views()->setTitles(title(m_compared), title(m_shown));
}

void ProjectWorkflow::showRun(int index)
{
    if (index < 0 || index >= int(m_runs.size()))
        return;
    m_shown = index;
    m_applying = true;
    m_remesh.show(m_runs[std::size_t(index)].outcome, m_runs[std::size_t(index)].decisions);
    m_applying = false;
    setModified(true);
    updatePanel();
    m_dock->show();
    m_bench.setStatus(tr("Showing run %1").arg(m_runs[std::size_t(index)].id));
}

void ProjectWorkflow::updatePanel()
{
    std::vector<RunsRow> rows;
    for (std::size_t i = 0; i < m_runs.size(); ++i) {
        const RemeshOutcome &o = m_runs[i].outcome;
        RunsRow row;
        row.id = m_runs[i].id;
        row.parameters = describeParams(o.params);
        row.sites = o.siteCount;
        row.vertices = qint64(o.comparison.output.mesh.vertices);
        row.triangles = qint64(o.comparison.output.mesh.triangles);
        row.valid = o.validity.valid;
        row.hausdorffPctBbox = o.comparison.hausdorff.symmetricPctBbox;
        row.meanQuality = o.comparison.output.mesh.meanQuality;
        row.reviewed = m_runs[i].decisions.reviewedCount();
        row.records = o.ledger ? int(o.ledger->size()) : 0;
        rows.push_back(row);
    }
    m_panel->setRuns(rows, m_shown, m_compared);
}

void ProjectWorkflow::fail(const Message &message, const QString &status)
{
    m_bench.addMessage(message);
    m_bench.showMessages();
    m_bench.setStatus(status);
}

void ProjectWorkflow::chooseProject()
{
    const std::unique_ptr<QSettings> settings = openSettings();
    const QString dir = settings->value(QStringLiteral("lastDirectory")).toString();
    const QString path = QFileDialog::getOpenFileName(m_bench.window(), tr("Open Project"), dir,
                                                      tr("StrataMesh projects (*.smproj)"));
    if (path.isEmpty())
        return;
    settings->setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    openProject(path);
}

bool ProjectWorkflow::openProject(const QString &path)
{
    if (m_bench.isBusy() || !m_bench.mayDiscardWork())
        return false;
    const QString could = tr("Could not open the project %1").arg(QFileInfo(path).fileName());
    auto pending = std::make_unique<Pending>();
    pending->path = QFileInfo(path).absoluteFilePath();
    try {
        pending->file = readProjectFile(pending->path);
    } catch (const std::exception &e) {
        fail(errorMessage(e, path), could);
        return false;
    }
    ProjectFile &file = pending->file;
    if (!file.inputIsSample && !QFileInfo::exists(file.inputPath)) {
        Message missing{Message::Severity::Warning,
                        tr("The project's input model is not where the project says: %1")
                            .arg(QDir::toNativeSeparators(file.inputPath)),
                        path,
                        0,
                        {}};
        m_bench.addMessage(missing);
        const QString found = m_locate(file.inputPath);
        if (found.isEmpty() || !QFileInfo::exists(found)) {
            fail({Message::Severity::Error,
                  tr("Project not opened: its input model %1 is missing")
                      .arg(QFileInfo(file.inputPath).fileName()),
                  path,
                  0,
                  {}},
                 could);
            return false;
        }
        file.inputPath = QFileInfo(found).absoluteFilePath();
        pending->relocated = true;
    }
    try {
        for (const ProjectRun &run : file.runs)
            pending->runs.push_back(readRunFolder(pending->path, run));
    } catch (const std::exception &e) {
        fail(errorMessage(e, path), could);
        return false;
    }
    // The input opens as any model does (worker thread, validity messages); onOpenFinished then
    // puts the runs back.
    OpenModelController *controller = m_openWorkflow.controller();
    const QString input = file.inputPath;
    const bool sample = file.inputIsSample;
    m_pending = std::move(pending);
    if (!(sample ? controller->openSample() : controller->openFile(input))) {
        m_pending.reset();
        return false;
    }
    return true;
}

void ProjectWorkflow::onOpenFinished(bool ok)
{
    if (!m_pending)
        return;
    std::unique_ptr<Pending> pending = std::move(m_pending);
    if (!ok) {
        m_bench.setStatus(tr("Could not open the project's input model — see Messages"));
        emit projectOpened(false);
        return;
    }
    install(*pending);
}

void ProjectWorkflow::install(Pending &pending)
{
    const std::shared_ptr<const Model> &input = m_bench.model();
    std::vector<Run> runs;
    try {
        for (std::size_t i = 0; i < pending.runs.size(); ++i) {
            const ProjectRun &entry = pending.file.runs[i];
            RunRead &read = pending.runs[i];
            const QString reportPath = runFolderPaths(pending.path, entry.folder).report;
            const QJsonObject &report = read.report;
            RemeshOutcome o = restoredOutcome(input, entry, read, reportPath);
            const int records = int(o.ledger->size());
            QString error;
            std::optional<ReviewDecisions> decisions =
                ReviewDecisions::fromJson(entry.review, records, &error);
            if (!decisions) {
                m_bench.addMessage(
                    {Message::Severity::Warning,
                     tr("Run %1: its review was not read (%2)").arg(entry.id).arg(error),
                     pending.path,
                     0,
                     {}});
                decisions = ReviewDecisions();
            }
            runs.push_back(
                {std::move(o), *decisions, report, pending.path, entry.id, entry.folder});
        }
    } catch (const std::exception &e) {
        fail(errorMessage(e, pending.path),
             tr("Could not open the project %1").arg(QFileInfo(pending.path).fileName()));
        emit projectOpened(false);
        return;
    }
    m_runs = std::move(runs);
    m_path = pending.path;
    emit pathChanged(m_path);
    m_shown = -1;
    const int shown = pending.file.shownRun >= 0 ? pending.file.shownRun : int(m_runs.size()) - 1;
    if (shown >= 0)
        showRun(shown);
    // Before the camera: the camera was saved in the exaggerated view's coordinates.
    const double exaggeration =
        pending.file.view.value(QLatin1String("vertical_exaggeration")).toDouble(1.0);
    if (exaggeration >= ExaggerationWorkflow::kMinimum
        && exaggeration <= ExaggerationWorkflow::kMaximum)
        m_bench.setVerticalExaggeration(exaggeration);
    applyCamera(pending.file.view.value(QLatin1String("camera")).toObject(),
                m_bench.inputView()->renderer()->GetActiveCamera());
    m_bench.inputView()->renderer()->ResetCameraClippingRange();
    m_bench.outputView()->renderer()->ResetCameraClippingRange();
    m_bench.render();
    m_remesh.markSaved();
    setModified(pending.relocated);
    updatePanel();
    m_dock->show();
    m_dock->raise();
    enableActions(m_bench.isBusy());
    m_bench.addMessage({Message::Severity::Info,
                        tr("Project %1 opened: %n run(s), read from its folder without remeshing",
                           nullptr, int(m_runs.size()))
                            .arg(QFileInfo(m_path).fileName()),
                        m_path,
                        0,
                        {}});
    if (pending.relocated)
        m_bench.addMessage({Message::Severity::Warning,
                            tr("The input model was found at %1: save the project to keep it")
                                .arg(QDir::toNativeSeparators(pending.file.inputPath)),
                            m_path,
                            0,
                            {}});
    m_bench.setStatus(tr("Opened project %1").arg(QFileInfo(m_path).fileName()));
    emit projectOpened(true);
}

bool ProjectWorkflow::save()
{
    return m_path.isEmpty() ? saveAs() : saveProject(m_path);
}

bool ProjectWorkflow::saveAs()
{
    if (!m_bench.model())
        return false;
    const std::unique_ptr<QSettings> settings = openSettings();
    const QString dir = m_path.isEmpty()
                            ? settings->value(QStringLiteral("lastDirectory")).toString()
                            : QFileInfo(m_path).absolutePath();
    QString path = QFileDialog::getSaveFileName(m_bench.window(), tr("Save Project"), dir,
                                                tr("StrataMesh projects (*.smproj)"));
    if (path.isEmpty())
        return false;
    if (!isProjectFile(path))
        path += QStringLiteral(".smproj");
    settings->setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    return saveProject(path);
}

bool ProjectWorkflow::saveProject(const QString &path)
{
    if (!m_bench.model())
        return false;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    const QString inputPath = m_bench.modelPath().isEmpty()
                                  ? QString()
                                  : QFileInfo(m_bench.modelPath()).absoluteFilePath();
    ProjectFile file;
    file.inputPath = inputPath;
    file.inputIsSample = inputPath.isEmpty();
    file.shownRun = m_shown;
    file.view.insert(QStringLiteral("vertical_exaggeration"), m_bench.verticalExaggeration());
    file.view.insert(QStringLiteral("camera"),
                     cameraJson(m_bench.inputView()->renderer()->GetActiveCamera()));
    std::vector<RunContent> contents;
    for (std::size_t i = 0; i < m_runs.size(); ++i) {
        Run &run = m_runs[i];
        const RemeshOutcome &o = run.outcome;
        ProjectRun entry;
        entry.id = run.id;
        entry.folder = run.folder;
        entry.params = o.params;
        entry.figures.sites = o.siteCount;
        entry.figures.vertices = qint64(o.comparison.output.mesh.vertices);
        entry.figures.triangles = qint64(o.comparison.output.mesh.triangles);
        entry.figures.valid = o.validity.valid;
        entry.figures.hausdorffPctBbox = o.comparison.hausdorff.symmetricPctBbox;
        entry.figures.meanQuality = o.comparison.output.mesh.meanQuality;
        entry.figures.ledgerRecords = int(o.ledger->size());
        entry.review = run.decisions.toJson();
        if (run.report.isEmpty()) {
            RemeshReportParts parts;
            parts.file = file.inputIsSample ? QStringLiteral("sample") : inputPath;
            parts.outputFile = QStringLiteral("output.ml");
            parts.input = o.input.get();
            parts.output = o.output.get();
            parts.params = &o.params;
            parts.ledger = o.ledger.get();
            parts.comparison = &o.comparison;
            parts.outputValidity = &o.validity;
            parts.facts = factsOf(o);
            run.report = remeshReportJson(parts);
        }
        const bool written = run.savedIn == absolute;
        contents.push_back({written ? nullptr : o.output.get(), o.ledger.get(), run.report});
        file.runs.push_back(std::move(entry));
    }
    try {
        writeProject(absolute, file, contents, inputPath);
    } catch (const std::exception &e) {
        fail(errorMessage(e, path), tr("Could not save the project"));
        return false;
    }
    m_path = absolute;
    emit pathChanged(m_path);
    for (Run &run : m_runs)
        run.savedIn = absolute;
    setModified(false);
    m_remesh.markSaved();
    m_bench.addMessage({Message::Severity::Info,
                        tr("Project saved with %n run(s)", nullptr, int(m_runs.size())),
                        absolute,
                        0,
                        {}});
    m_bench.setStatus(tr("Saved %1").arg(QFileInfo(absolute).fileName()));
    return true;
}

} // namespace stratamesh
