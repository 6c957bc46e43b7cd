#include "export_workflow.h"

#include "disabled_reason.h"
#include "error_message.h"
#include "export_controller.h"
#include "hybrid_workflow.h"
#include "remesh_workflow.h"
#include "tetmesh_workflow.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>

#include <algorithm>

namespace stratamesh {

namespace {

// What the dialog needs of a model: its surface names, for the single-surface formats.
QStringList surfaceNames(const Model &model)
{
    QStringList names;
    for (const Surface &s : model.surfaces)
        names << QString::fromStdString(s.name);
    return names;
}

// A mesh of tetrahedra goes to a TSolid too; pyramids or prisms need a format that keeps them.
ExportData meshData(const VolumeMesh &mesh)
{
    const bool mixed = std::any_of(mesh.cells.begin(), mesh.cells.end(),
                                   [](const Cell &c) { return c.type != CellType::Tet; });
    return mixed ? ExportData::HybridMesh : ExportData::TetMesh;
}

} // namespace

ExportWorkflow::ExportWorkflow(Workbench &bench, RemeshWorkflow &remesh,
                               const TetmeshWorkflow &tetmesh, const HybridWorkflow &hybrid,
                               QObject *parent)
    : Workflow(bench, parent), m_remesh(remesh), m_tetmesh(tetmesh), m_hybrid(hybrid),
      m_controller(new ExportController(this)), m_separator(separator()),
      m_export(new QAction(this))
{
    m_export->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    m_export->setEnabled(false);
    connect(m_export, &QAction::triggered, this, &ExportWorkflow::chooseExport);
    setDisabledReason(m_export, [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    });
    connect(m_controller, &ExportController::succeeded, this, &ExportWorkflow::onSucceeded);
    connect(m_controller, &ExportController::failed, this, &ExportWorkflow::onFailed);
    // A write can take seconds for a large mesh: the window stays live, with a busy cursor.
    connect(m_controller, &ExportController::started, this,
            [] { QApplication::setOverrideCursor(Qt::BusyCursor); });
    connect(m_controller, &ExportController::finished, this,
            [] { QApplication::restoreOverrideCursor(); });
    relay(m_controller);
}

// A running write finishes (it cannot be cancelled) before the data it reads may go.
ExportWorkflow::~ExportWorkflow()
{
    m_controller->disconnect(this);
    delete m_controller;
}

QList<QAction *> ExportWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::File)
        return {m_separator, m_export};
    return {};
}

WorkflowJob *ExportWorkflow::job() const
{
    return m_controller;
}

void ExportWorkflow::retranslate()
{
    m_export->setText(tr("&Export…"));
    m_export->setStatusTip(
        tr("Write the model, its remesh or a volume mesh to another file format"));
}

void ExportWorkflow::enableActions(bool busy)
{
    m_export->setEnabled(!busy && m_bench.model());
}

QList<ExportSubject> ExportWorkflow::subjects() const
{
    const QString base = m_bench.modelPath().isEmpty()
                             ? QStringLiteral("model")
                             : QFileInfo(m_bench.modelPath()).completeBaseName();
    QList<ExportSubject> out;

    // Never offered under the open model's own name, which the export would refuse.
    ExportSubject input{
        tr("Input model"), {}, ExportData::SurfaceModel, {}, base + QStringLiteral("_export")};
    if (const auto &model = m_bench.model())
        input.surfaceNames = surfaceNames(*model);
    else
        input.unavailable = tr("No model is open");
    out << input;

    ExportSubject remeshed{
        tr("Remeshed model"), {}, ExportData::SurfaceModel, {}, base + QStringLiteral("_remeshed")};
    if (const auto &outcome = m_remesh.outcome())
        remeshed.surfaceNames = surfaceNames(*outcome->output);
    else
        remeshed.unavailable = tr("No remeshed model: run Mesh > Remesh… first");
    out << remeshed;

    const auto &tets = m_tetmesh.outcome();
    const auto tetSubject = [&](const QString &label, const QString &name,
                                const std::shared_ptr<const TetmeshSide> &side,
                                const QString &failed) {
        ExportSubject s{label, {}, ExportData::TetMesh, {}, name};
        if (!tets)
            s.unavailable = tr("No TetGen mesh: run Mesh > Tetrahedralise… first");
        else if (!side)
            s.unavailable = tr("The last tetrahedralisation did not mesh the remeshed model");
        else if (const auto mesh = TetmeshOutcome::meshOf(side))
            s.data = meshData(*mesh);
        else
            s.unavailable = failed;
        return s;
    };
    out << tetSubject(tr("TetGen mesh of the input"), base + QStringLiteral("_tets"),
                      tets ? tets->inputSide : nullptr, tr("TetGen failed on the input model"));
    out << tetSubject(tr("TetGen mesh of the remesh"), base + QStringLiteral("_remeshed_tets"),
                      tets ? tets->outputSide : nullptr, tr("TetGen failed on the remeshed model"));

    ExportSubject hybrid{
        tr("Hybrid mesh"), {}, ExportData::HybridMesh, {}, base + QStringLiteral("_hybrid")};
    if (const auto &outcome = m_hybrid.outcome(); outcome && outcome->mesh())
        hybrid.data = meshData(*outcome->mesh());
    else
        hybrid.unavailable = tr("No hybrid mesh: run Mesh > Hybrid Mesh… first");
    out << hybrid;
    return out;
}

void ExportWorkflow::chooseExport()
{
    QSettings settings;
    QString dir = settings.value(QStringLiteral("lastExportDirectory")).toString();
    if (dir.isEmpty() && !m_bench.modelPath().isEmpty())
        dir = QFileInfo(m_bench.modelPath()).absolutePath();
    ExportDialog dialog(subjects(), dir, m_bench.window());
    if (dialog.exec() != QDialog::Accepted || dialog.subject() < 0)
        return;
    const QString path = dialog.path();
    settings.setValue(QStringLiteral("lastExportDirectory"), QFileInfo(path).absolutePath());
    start(Subject(dialog.subject()), path, dialog.options());
}

bool ExportWorkflow::start(Subject subject, const QString &path, const ExportOptions &options)
{
    const QList<ExportSubject> all = subjects();
    const ExportSubject &chosen = all[int(subject)];
    if (!chosen.unavailable.isEmpty()) {
        refuse(path, chosen.unavailable);
        return false;
    }
    const FileFormat *format = findFormat(path.toStdString());
    if (format == nullptr || !format->writes()) {
        refuse(path, tr("cannot tell the format from the extension (use %1)")
                         .arg(QString::fromStdString(extensionList(FormatUse::Export))));
        return false;
    }
    if (const QString why = ExportDialog::refusal(*format, chosen.data); !why.isEmpty()) {
        refuse(path, why);
        return false;
    }

    ExportRequest request;
    request.path = path;
    request.inputPath = m_bench.modelPath();
    request.options = options;
    switch (subject) {
    case Subject::InputModel:
        request.model = m_bench.model();
        request.role = QStringLiteral("exported model");
        break;
    case Subject::RemeshedModel:
        request.model = m_remesh.outcome()->output;
        request.role = QStringLiteral("remeshed model");
        break;
    case Subject::InputTets:
        request.mesh = TetmeshOutcome::meshOf(m_tetmesh.outcome()->inputSide);
        request.role = QStringLiteral("TetGen mesh");
        break;
    case Subject::RemeshTets:
        request.mesh = TetmeshOutcome::meshOf(m_tetmesh.outcome()->outputSide);
        request.role = QStringLiteral("TetGen mesh");
        break;
    case Subject::HybridMesh:
        request.mesh = m_hybrid.outcome()->mesh();
        request.role = QStringLiteral("hybrid mesh");
        break;
    }
    m_savesRemesh = subject == Subject::RemeshedModel
                    && formatLosses(*format, ExportData::SurfaceModel).empty();
    if (!m_controller->start(request)) {
        refuse(path, tr("another run is under way"));
        return false;
    }
    m_bench.setStatus(tr("Exporting %1…").arg(QFileInfo(path).fileName()));
    return true;
}

void ExportWorkflow::onSucceeded(const QString &path, const QString &format,
                                 qulonglong untaggedSkipped, qint64 milliseconds)
{
    Message message{
        Message::Severity::Info,
        tr("Exported as %1 in %2 s").arg(format).arg(double(milliseconds) / 1000.0, 0, 'f', 2),
        path,
        0,
        {}};
    m_bench.addMessage(message);
    if (m_savesRemesh)
        m_remesh.markSaved();
    if (untaggedSkipped > 0)
        m_bench.addMessage({Message::Severity::Warning,
                            tr("%1 elements without a region, surface or line were left out, as "
                               "Gmsh does; “Keep elements without a group” keeps them")
                                .arg(untaggedSkipped),
                            path,
                            0,
                            {}});
    m_bench.setStatus(tr("Exported %1").arg(QFileInfo(path).fileName()));
}

void ExportWorkflow::onFailed(const Message &error)
{
    Message shown = error;
    shown.text = tr("Export failed: %1").arg(error.text);
    m_bench.addMessage(shown);
    m_bench.showMessages();
    m_bench.setStatus(tr("Could not export"));
}

void ExportWorkflow::refuse(const QString &path, const QString &cause)
{
    onFailed({Message::Severity::Error, cause, path, 0, {}});
}

} // namespace stratamesh
