// File > Export… driven through its dialog on modelA1 and its remesh: the remesh as Gmsh 4.1 and
// 2.2 and as VTK, read back by `stratamesh-cli info` with the output model's counts; the warning
// line of a format that drops something; entries that cannot be taken disabled with the reason;
// an export over the open model's file refused, leaving it unchanged; a folder that cannot take
// the file gives an error naming it and leaves nothing; a TetGen mesh as .vtu, its cells counted
// by our reader and by meshio.
#include "cli_runner.h"
#include "export_controller.h"
#include "export_dialog.h"
#include "export_workflow.h"
#include "hybrid_workflow.h"
#include "io/mesh_reader.h"
#include "main_window.h"
#include "message_panel.h"
#include "open_workflow.h"
#include "quality/mesh_statistics.h"
#include "remesh/surface_remesher.h"
#include "remesh_workflow.h"
#include "support/test_data.h"
#include "tetmesh_workflow.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <functional>
#include <unistd.h>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

using Subject = ExportWorkflow::Subject;

bool entryEnabled(const QComboBox *box, int index)
{
    const auto *model = qobject_cast<const QStandardItemModel *>(box->model());
    return model && model->item(index) && model->item(index)->isEnabled();
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QJsonObject info(const QString &path)
{
    const test::CliRun run = test::runCli({QStringLiteral("info"), path, QStringLiteral("--json")});
    if (!run.finished || run.exitCode != 0) {
        qWarning("info failed: %s", qPrintable(run.err));
        return {};
    }
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

} // namespace

class TestGuiExport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        QVERIFY(m_dir.isValid());
        STRATAMESH_REQUIRE_DATA(source, "modelA1.ml");
        m_input = m_dir.filePath(QStringLiteral("modelA1.ml"));
        QVERIFY(QFile::copy(source, m_input));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_export = m_window->findChild<ExportWorkflow *>();
        QVERIFY(m_export);
        QVERIFY(!m_export->exportAction()->isEnabled()); // nothing open yet

        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openFile(m_input);
        QVERIFY(loaded.wait(kTimeoutMs) && loaded.first().first().toBool());
        QVERIFY(m_export->exportAction()->isEnabled());
    }

    void cleanupTestCase() { m_window.reset(); }

    // Before a remesh or a tetrahedralisation only the input can go; the rest say why.
    void unavailableEntriesSayWhy()
    {
        const QList<ExportSubject> subjects = m_export->subjects();
        QCOMPARE(subjects.size(), 5);
        QVERIFY(subjects[int(Subject::InputModel)].unavailable.isEmpty());
        QVERIFY(subjects[int(Subject::RemeshedModel)].unavailable.contains("Remesh"));
        QVERIFY(subjects[int(Subject::InputTets)].unavailable.contains("Tetrahedralise"));
        QVERIFY(subjects[int(Subject::HybridMesh)].unavailable.contains("Hybrid"));

        ExportDialog dialog(subjects, m_dir.path());
        QCOMPARE(dialog.subject(), int(Subject::InputModel));
        QVERIFY(!entryEnabled(dialog.subjectBox(), int(Subject::RemeshedModel)));
        QCOMPARE(dialog.subjectBox()->itemData(int(Subject::InputTets), Qt::ToolTipRole).toString(),
                 subjects[int(Subject::InputTets)].unavailable);
        // A TSolid holds tetrahedra: refused for a surface model, with the reason.
        const int so = dialog.formatBox()->findData(QStringLiteral(".so"));
        QVERIFY(so >= 0 && !entryEnabled(dialog.formatBox(), so));
        QVERIFY(dialog.formatBox()->itemData(so, Qt::ToolTipRole).toString().contains("tetra"));
        QVERIFY(!dialog.setFormat(QStringLiteral(".so")));
        // The file follows the format, and a typed extension chooses the format.
        QVERIFY(dialog.setFormat(QStringLiteral(".vtu")));
        QCOMPARE(dialog.path(), m_dir.filePath(QStringLiteral("modelA1_export.vtu")));
        dialog.setPath(m_dir.filePath(QStringLiteral("other.ts")));
        QCOMPARE(dialog.format()->extension, std::string(".ts"));
        QVERIFY(dialog.surfaceBox()->isVisibleTo(&dialog));
        QCOMPARE(dialog.surfaceBox()->itemData(0).toInt(), -1); // "All surfaces" for a TSurf
        QVERIFY(dialog.warning().contains("regions"));
        QVERIFY(!dialog.mshVersionBox()->isVisibleTo(&dialog));
        // OBJ: one surface, named nothing.
        QVERIFY(dialog.setFormat(QStringLiteral(".obj")));
        QCOMPARE(dialog.path(), m_dir.filePath(QStringLiteral("other.obj")));
        QVERIFY(dialog.warning().contains("surface names"));
        QVERIFY(dialog.warning().contains("every surface but the chosen one"));
        QCOMPARE(dialog.surfaceBox()->itemData(0).toInt(), 0); // no "all" for OBJ
        QVERIFY(dialog.setFormat(QStringLiteral(".ml")));
        QVERIFY(dialog.warning().isEmpty());
        QVERIFY(!dialog.warningLabel()->isVisibleTo(&dialog));
    }

    void remeshThenExportAsGmsh41()
    {
        RemeshParams params;
        params.sites = 300;
        params.iterations = 20;
        QSignalSpy remeshed(m_window->remeshWorkflow(), &RemeshWorkflow::finished);
        QVERIFY(m_window->remeshWorkflow()->start(params));
        QVERIFY(remeshed.wait(kTimeoutMs) && remeshed.first().first().toBool());

        const QString path = m_dir.filePath(QStringLiteral("remeshed41.msh"));
        QString warning;
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                QVERIFY(d.setFormat(QStringLiteral(".msh")));
                QVERIFY(d.mshVersionBox()->isVisibleTo(&d));
                d.mshVersionBox()->setCurrentIndex(
                    d.mshVersionBox()->findData(int(GmshWriteOptions::Version::V41)));
                d.pathEdit()->setText(m_dir.filePath(QStringLiteral("remeshed41")));
                d.pathEdit()->editingFinished();
                QCOMPARE(d.path(), path);
                warning = d.warningLabel()->isVisibleTo(&d) ? d.warningLabel()->text() : QString();
                QVERIFY(d.grab().save(kShots + "/export_dialog_msh.png"));
            },
            true));
        QVERIFY2(warning.contains("feature types"), qPrintable(warning));
        QVERIFY(!warning.contains("surface names"));
        // Not all of the remesh is in the file: it still counts as unsaved.
        QVERIFY(!m_window->remeshWorkflow()->unsavedWork().isEmpty());
        QVERIFY(readAll(path).startsWith("$MeshFormat\n4.1 "));
        checkCounts(path, true);
    }

    void exportAsGmsh22()
    {
        const QString path = m_dir.filePath(QStringLiteral("remeshed22.msh"));
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                QVERIFY(d.setFormat(QStringLiteral(".msh")));
                d.mshVersionBox()->setCurrentIndex(
                    d.mshVersionBox()->findData(int(GmshWriteOptions::Version::V22)));
                d.setPath(path);
            },
            true));
        QVERIFY(readAll(path).startsWith("$MeshFormat\n2.2 "));
        checkCounts(path, true);
    }

    void exportAsVtu()
    {
        const QString path = m_dir.filePath(QStringLiteral("remeshed.vtu"));
        QString warning = QStringLiteral("unset");
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                d.setPath(path); // the extension chooses the format
                QCOMPARE(d.format()->extension, std::string(".vtu"));
                warning = d.warning();
            },
            true));
        QVERIFY2(warning.isEmpty(), qPrintable(warning)); // VTK keeps names, types, regions
        QVERIFY(m_window->remeshWorkflow()->unsavedWork().isEmpty()); // so the remesh is saved
        QVERIFY(readAll(path).contains("UnstructuredGrid"));
        checkCounts(path, true);
    }

    // The open model's own file is never written over, whatever its format.
    void exportOverTheInputRefused()
    {
        const QByteArray before = readAll(m_input);
        const int messages = m_window->messagePanel()->count();
        QVERIFY(!exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                d.setPath(m_input);
            },
            true));
        QCOMPARE(readAll(m_input), before);
        const Message last = lastMessage(messages);
        QCOMPARE(last.severity, Message::Severity::Error);
        QVERIFY(QFileInfo(last.file) == QFileInfo(m_input));
        QVERIFY2(last.text.contains("input"), qPrintable(last.text));
        QCOMPARE(entries(),
                 QStringList({"modelA1.ml", "remeshed.vtu", "remeshed22.msh", "remeshed41.msh"}));
    }

    // A folder that does not take the file: an error naming it and its cause, no file left.
    void unwritableFolderLeavesNothing()
    {
        QTemporaryDir other;
        QString folder;
        if (::geteuid() != 0) {
            folder = other.filePath(QStringLiteral("locked"));
            QVERIFY(QDir().mkpath(folder));
            QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        } else { // root writes anywhere, but not below a plain file
            folder = other.filePath(QStringLiteral("plain.txt"));
            QFile f(folder);
            QVERIFY(f.open(QIODevice::WriteOnly));
        }
        const QString path = QDir(folder).filePath(QStringLiteral("out.vtu"));
        const int messages = m_window->messagePanel()->count();
        QVERIFY(!exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                d.setPath(path);
            },
            true));
        const Message last = lastMessage(messages);
        QCOMPARE(last.severity, Message::Severity::Error);
        QVERIFY2(last.file.contains(QStringLiteral("out.vtu")), qPrintable(last.file));
        QVERIFY2(last.text.startsWith(QStringLiteral("Export failed: ")), qPrintable(last.text));
        QVERIFY(!QFileInfo::exists(path));
        const QStringList left =
            QDir(other.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
        QCOMPARE(left.size(), 1); // the folder (or the plain file) alone
        if (::geteuid() != 0) {
            QVERIFY(QDir(folder)
                        .entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot)
                        .isEmpty());
            QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner
                                              | QFileDevice::ExeOwner);
        }
    }

    // TetGen's mesh of the input as .vtu: meshio counts its tetrahedra.
    void tetgenMeshAsVtu()
    {
        TetgenParams params;
        params.timeLimitSeconds = 60.0;
        QSignalSpy meshed(m_window->tetmeshWorkflow(), &TetmeshWorkflow::finished);
        QVERIFY(m_window->tetmeshWorkflow()->start(params, false));
        QVERIFY(meshed.wait(kTimeoutMs) && meshed.first().first().toBool());
        const auto mesh = TetmeshOutcome::meshOf(m_window->tetmeshWorkflow()->outcome()->inputSide);
        QVERIFY(mesh && !mesh->cells.empty());

        const QString path = m_dir.filePath(QStringLiteral("tets.vtu"));
        bool vtpRefused = false;
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::InputTets));
                const int vtp = d.formatBox()->findData(QStringLiteral(".vtp"));
                const int obj = d.formatBox()->findData(QStringLiteral(".obj"));
                vtpRefused =
                    !entryEnabled(d.formatBox(), vtp) && !entryEnabled(d.formatBox(), obj)
                    && entryEnabled(d.formatBox(), d.formatBox()->findData(QStringLiteral(".so")));
                QVERIFY(d.setFormat(QStringLiteral(".vtu")));
                d.setPath(path);
                QVERIFY(d.grab().save(kShots + "/export_dialog_tets.png"));
                d.formatBox()->showPopup();
                QTest::qWait(200);
                QVERIFY(d.formatBox()->view()->window()->grab().save(kShots
                                                                     + "/export_formats_tets.png"));
                d.formatBox()->hidePopup();
            },
            true));
        QVERIFY(vtpRefused);
        // Our reader, then meshio (Debian's python3-meshio) when an interpreter has it.
        const VolumeMesh back = readVolumeMesh(path.toStdString());
        QCOMPARE(back.cells.size(), mesh->cells.size());
        QCOMPARE(back.points.size(), mesh->points.size());
        QString counted;
        for (const QString &python :
             {QStringLiteral("/usr/bin/python3"), QStringLiteral("python3")}) {
            QProcess p;
            p.start(python, {QStringLiteral("-c"),
                             QStringLiteral("import sys, meshio; m = meshio.read(sys.argv[1]); "
                                            "print(sum(len(c.data) for c in m.cells if c.type == "
                                            "'tetra'), len(m.points))"),
                             path});
            if (p.waitForFinished(60000) && p.exitStatus() == QProcess::NormalExit
                && p.exitCode() == 0) {
                counted = QString::fromUtf8(p.readAllStandardOutput()).trimmed();
                break;
            }
        }
        qInfo("TetGen mesh: %zu tets, %zu points; meshio read %s", mesh->cells.size(),
              mesh->points.size(), counted.isEmpty() ? "nothing (no meshio)" : qPrintable(counted));
        if (!counted.isEmpty())
            QCOMPARE(counted,
                     QStringLiteral("%1 %2").arg(mesh->cells.size()).arg(mesh->points.size()));
    }

    // One surface of the remesh as OBJ, chosen in the dialog: `info` reads that surface alone.
    void oneSurfaceAsObj()
    {
        const Model &output = *m_window->remeshWorkflow()->outcome()->output;
        QVERIFY(output.surfaces.size() > 3);
        const QString path = m_dir.filePath(QStringLiteral("surface.obj"));
        QString warning;
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::RemeshedModel));
                d.setPath(path);
                QVERIFY(d.surfaceBox()->isVisibleTo(&d));
                QCOMPARE(d.surfaceBox()->count(), int(output.surfaces.size()));
                d.surfaceBox()->setCurrentIndex(3);
                QCOMPARE(d.options().surface, 3);
                warning = d.warning();
            },
            true));
        QVERIFY2(warning.contains("every surface but the chosen one"), qPrintable(warning));
        QVERIFY(warning.contains("surface names") && warning.contains("regions"));
        const QJsonObject read = info(path);
        QCOMPARE(read.value("mesh").toObject().value("triangles").toInteger(),
                 qint64(output.surfaces[3].triangles.size()));
        QCOMPARE(read.value("counts").toObject().value("all").toObject().value("surfaces").toInt(),
                 1);
    }

    // A hybrid mesh goes only where pyramids and prisms are kept; as Gmsh 4.1, every cell of
    // every type comes back.
    void hybridMeshAsMsh()
    {
        HybridParams params;
        params.sites = 300;
        QSignalSpy built(m_window->hybridWorkflow(), &HybridWorkflow::finished);
        QVERIFY(m_window->hybridWorkflow()->start(params));
        QVERIFY(built.wait(kTimeoutMs) && built.first().first().toBool());
        const auto mesh = m_window->hybridWorkflow()->outcome()->mesh();
        QVERIFY(mesh
                && mesh->countCells(CellType::Prism) + mesh->countCells(CellType::Pyramid) > 0);
        QCOMPARE(m_export->subjects()[int(Subject::HybridMesh)].data, ExportData::HybridMesh);

        const QString path = m_dir.filePath(QStringLiteral("hybrid.msh"));
        QString soWhy;
        QVERIFY(exportThroughDialog(
            [&](ExportDialog &d) {
                d.subjectBox()->setCurrentIndex(int(Subject::HybridMesh));
                const int so = d.formatBox()->findData(QStringLiteral(".so"));
                if (!entryEnabled(d.formatBox(), so))
                    soWhy = d.formatBox()->itemData(so, Qt::ToolTipRole).toString();
                QVERIFY(d.setFormat(QStringLiteral(".msh")));
                d.setPath(path);
            },
            true));
        QVERIFY2(soWhy.contains("pyramids and prisms"), qPrintable(soWhy));
        const VolumeMesh back = readVolumeMesh(path.toStdString());
        for (const CellType type : {CellType::Tet, CellType::Pyramid, CellType::Prism})
            QCOMPARE(back.countCells(type), mesh->countCells(type));
        qInfo("hybrid mesh: %zu tets, %zu pyramids, %zu prisms read back from .msh",
              back.countCells(CellType::Tet), back.countCells(CellType::Pyramid),
              back.countCells(CellType::Prism));
    }

    // In French the dialog and its warning are French, and still fit.
    void frenchDialog()
    {
        QCOMPARE(installTranslations(QStringLiteral("fr")), QStringLiteral("fr"));
        // The language change reaches the widgets through posted events: let it pass before the
        // dialog is made, as at start-up (else its button box would reset "Export" to "OK").
        QCoreApplication::processEvents();
        {
            ExportDialog dialog(m_export->subjects(), m_dir.path(), m_window.get());
            dialog.setSubject(int(Subject::RemeshedModel));
            QVERIFY(dialog.setFormat(QStringLiteral(".obj")));
            dialog.show();
            QVERIFY(QTest::qWaitForWindowExposed(&dialog));
            QVERIFY2(dialog.warning().contains(QStringLiteral("ne conserve pas")),
                     qPrintable(dialog.warning()));
            QCOMPARE(dialog.subjectBox()->currentText(), QStringLiteral("Modèle remaillé"));
            QCOMPARE(dialog.exportButton()->text(), QStringLiteral("E&xporter"));
            QVERIFY(dialog.grab().save(kShots + "/export_dialog_fr.png"));
        }
        installTranslations(QStringLiteral("en"));
    }

private:
    // Opens File > Export…, lets `fill` set the dialog's widgets, presses Export and waits for the
    // write; true when it succeeded.
    bool exportThroughDialog(const std::function<void(ExportDialog &)> &fill, bool accept)
    {
        QSignalSpy finished(m_export, &Workflow::finished);
        bool seen = false;
        QTimer poll;
        poll.setInterval(20);
        connect(&poll, &QTimer::timeout, this, [&] {
            auto *dialog = m_window->findChild<ExportDialog *>();
            if (!dialog || !dialog->isVisible())
                return;
            poll.stop();
            seen = true;
            fill(*dialog);
            if (accept && dialog->exportButton()->isEnabled())
                dialog->exportButton()->click();
            else
                dialog->reject();
        });
        poll.start();
        m_export->exportAction()->trigger();
        poll.stop();
        if (!seen)
            return false;
        return finished.wait(kTimeoutMs) && finished.first().first().toBool();
    }

    // `info` reads the file back with the counts of the remeshed model.
    void checkCounts(const QString &path, bool surfaces)
    {
        const RemeshOutcome &outcome = *m_window->remeshWorkflow()->outcome();
        const MeshStatistics expected = computeMeshStatistics(*outcome.output);
        const QJsonObject read = info(path);
        QVERIFY(!read.isEmpty());
        const QJsonObject mesh = read.value("mesh").toObject();
        qInfo("%s: %lld vertices, %lld triangles, %d surfaces (output: %zu, %zu, %d)",
              qPrintable(QFileInfo(path).fileName()), mesh.value("vertices").toInteger(),
              mesh.value("triangles").toInteger(),
              read.value("counts").toObject().value("all").toObject().value("surfaces").toInt(),
              expected.vertices, expected.triangles, outcome.counts.all.surfaces);
        QCOMPARE(mesh.value("triangles").toInteger(), qint64(expected.triangles));
        QCOMPARE(mesh.value("vertices").toInteger(), qint64(expected.vertices));
        if (surfaces)
            QCOMPARE(
                read.value("counts").toObject().value("all").toObject().value("surfaces").toInt(),
                outcome.counts.all.surfaces);
    }

    Message lastMessage(int before) const
    {
        const MessagePanel *panel = m_window->messagePanel();
        return panel->count() > before ? panel->message(panel->count() - 1) : Message{};
    }

    QStringList entries() const
    {
        return QDir(m_dir.path())
            .entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
    }

    QTemporaryDir m_dir;
    QString m_input;
    std::unique_ptr<MainWindow> m_window;
    ExportWorkflow *m_export = nullptr;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiExport test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_export.moc"
