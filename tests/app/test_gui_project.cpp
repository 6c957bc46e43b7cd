// The Runs dock and project files end to end on modelA1: two remesh runs listed, a review decision
// kept per run, the run shown chosen and undone; the project saved (no dirty marker after) and
// reopened in a new window with the same runs, figures, decisions and output model, and no engine
// run; a moved input located through the callback; a moved runs folder, a newer schema and
// malformed JSON refused with messages naming the cause.
#include "comparison_table.h"
#include "ledger_panel.h"
#include "ledger_table_model.h"
#include "main_window.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "project_workflow.h"
#include "remesh_controller.h"
#include "remesh_workflow.h"
#include "runs_panel.h"
#include "support/test_data.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;

bool waitForRemesh(MainWindow &window, int sites)
{
    RemeshParams params;
    params.sites = sites;
    params.iterations = 20;
    QSignalSpy finished(window.remeshWorkflow(), &RemeshWorkflow::finished);
    if (!window.remeshWorkflow()->start(params))
        return false;
    return finished.wait(kTimeoutMs) && finished.first().first().toBool();
}

std::unique_ptr<MainWindow> newWindow(int *asked)
{
    auto window = std::make_unique<MainWindow>();
    window->resize(1400, 900);
    window->show();
    window->workbench()->setAsk([asked](const QString &) {
        ++*asked;
        return QMessageBox::Discard;
    });
    // Never a file dialog in a test: a missing input is not found unless a test says where.
    window->projectWorkflow()->setLocate([](const QString &) { return QString(); });
    return window;
}

// The text of every message, one per line.
QString allMessages(const MainWindow &window)
{
    QString text;
    for (int i = 0; i < window.messagePanel()->count(); ++i)
        text += window.messagePanel()->message(i).text + QLatin1Char('\n');
    return text;
}

struct Figures {
    int sites;
    std::size_t vertices, triangles, records;
    bool valid;
    double hausdorff, meanQ;
    int paramSites, iterations;
    int sizedSites, pocketsOpened;
    double smallestSize;
};

Figures figuresOf(const ProjectWorkflow::Run &run)
{
    const RemeshOutcome &o = run.outcome;
    return {o.siteCount,
            o.comparison.output.mesh.vertices,
            o.comparison.output.mesh.triangles,
            o.ledger->size(),
            o.validity.valid,
            o.comparison.hausdorff.symmetricPctBbox,
            o.comparison.output.mesh.meanQuality,
            o.params.sites,
            o.params.iterations,
            o.sizedSiteCount,
            o.pocketsOpened,
            o.smallestCellSize};
}

} // namespace

class TestGuiProject : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        STRATAMESH_REQUIRE_DATA(a1, "modelA1.ml");
        QVERIFY(m_dir.isValid());
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("models")));
        m_input = m_dir.filePath(QStringLiteral("models/modelA1.ml"));
        QVERIFY(QFile::copy(a1, m_input));
        m_project = m_dir.filePath(QStringLiteral("study.smproj"));
    }

    void runsAreKeptSavedAndReopened()
    {
        int asked = 0;
        auto window = newWindow(&asked);
        QVERIFY(QTest::qWaitForWindowExposed(window.get()));
        QSignalSpy opened(window->openWorkflow(), &OpenWorkflow::finished);
        window->openFile(m_input);
        QVERIFY(opened.wait(kTimeoutMs));
        QVERIFY(opened.first().first().toBool());
        QVERIFY(!window->isWindowModified());
        QVERIFY(window->windowTitle().contains(QStringLiteral("[*]")));

        QVERIFY(waitForRemesh(*window, 150));
        QVERIFY(waitForRemesh(*window, 300));
        ProjectWorkflow *project = window->projectWorkflow();
        RemeshWorkflow *remesh = window->remeshWorkflow();
        QCOMPARE(project->runs().size(), std::size_t(2));
        QCOMPARE(project->shownRun(), 1);
        QVERIFY(window->isWindowModified()); // a new run
        QCOMPARE(project->runs()[0].outcome.params.sites, 150);
        QCOMPARE(project->runs()[1].outcome.params.sites, 300);
        QVERIFY(project->runs()[0].outcome.output != project->runs()[1].outcome.output);
        QTableWidget *table = project->runsPanel()->table();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(1, 2)->text(), QString::number(project->runs()[1].outcome.siteCount));
        QVERIFY(project->runsDock()->isVisible());

        // A review decision belongs to the run shown.
        QVERIFY(!project->runs()[1].outcome.ledger->empty());
        ReviewDecisions decisions;
        decisions.setDecision(0, {ReviewVerdict::Accepted, QStringLiteral("throw kept")});
        remesh->setDecisions(decisions);
        QCOMPARE(project->runs()[1].decisions, decisions);
        QVERIFY(project->runs()[0].decisions.isEmpty());

        // Choosing a run in the table shows it; Undo shows the one before.
        QUndoStack *undo = window->workbench()->undoStack();
        const int commands = undo->count();
        table->selectRow(0);
        QCOMPARE(project->shownRun(), 0);
        QCOMPARE(undo->count(), commands + 1);
        QCOMPARE(remesh->outcome()->output, project->runs()[0].outcome.output);
        QCOMPARE(window->outputScene()->model(), project->runs()[0].outcome.output);
        QVERIFY(remesh->decisions().isEmpty());
        QCOMPARE(remesh->ledgerPanel()->tableModel()->rowCount(),
                 int(project->runs()[0].outcome.ledger->size()));
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        project->runsDock()->raise();
        QTest::qWait(200);
        QVERIFY(saveWindowScreenshot(window.get(), shots + "/project_runs.png"));
        undo->undo();
        QCOMPARE(project->shownRun(), 1);
        QCOMPARE(remesh->outcome()->output, project->runs()[1].outcome.output);
        QCOMPARE(remesh->decisions(), decisions);
        undo->redo();
        QCOMPARE(project->shownRun(), 0);
        undo->undo();
        QCOMPARE(project->shownRun(), 1);

        // Unsaved: closing asks once for the remeshed model and the project; Cancel keeps the
        // window.
        QStringList questions;
        window->workbench()->setAsk([&questions](const QString &question) {
            questions.append(question);
            return QMessageBox::Cancel;
        });
        QVERIFY(!window->close());
        QCOMPARE(questions.size(), 1);
        QVERIFY2(questions.first().contains(QStringLiteral("project's runs")),
                 qPrintable(questions.first()));
        QVERIFY2(questions.first().contains(QStringLiteral("remeshed model")),
                 qPrintable(questions.first()));
        QVERIFY(window->isVisible());
        window->workbench()->setAsk([&asked](const QString &) {
            ++asked;
            return QMessageBox::Discard;
        });

        // The camera is part of the view state kept.
        vtkCamera *camera = window->view()->renderer()->GetActiveCamera();
        camera->Azimuth(40.0);
        camera->Elevation(15.0);
        double savedPosition[3];
        camera->GetPosition(savedPosition);

        // A save that cannot be written says where and why, and leaves the project unsaved.
        const QString blocker = m_dir.filePath(QStringLiteral("not_a_folder"));
        {
            QFile file(blocker);
            QVERIFY(file.open(QIODevice::WriteOnly));
        }
        const int errors = window->messagePanel()->count(Message::Severity::Error);
        QVERIFY(!project->saveProject(blocker + QStringLiteral("/x.smproj")));
        QCOMPARE(window->messagePanel()->count(Message::Severity::Error), errors + 1);
        const Message failed = window->messagePanel()->message(window->messagePanel()->count() - 1);
        QCOMPARE(failed.severity, Message::Severity::Error);
        QVERIFY2(failed.file.contains(QStringLiteral("not_a_folder")), qPrintable(failed.file));
        QVERIFY2(failed.text.contains(QStringLiteral("cannot create")), qPrintable(failed.text));
        QVERIFY(window->isWindowModified());
        QVERIFY(project->projectPath().isEmpty());

        // Save: the folder, then the project; no dirty marker after.
        QVERIFY(project->saveProject(m_project));
        QVERIFY(!window->isWindowModified());
        QCOMPARE(project->projectPath(), QFileInfo(m_project).absoluteFilePath());
        for (const char *run : {"run-001", "run-002"})
            for (const char *file : {"output.ml", "report.json", "ledger.json"})
                QVERIFY2(QFileInfo::exists(
                             m_dir.filePath(QStringLiteral("study_runs/%1/%2")
                                                .arg(QLatin1String(run), QLatin1String(file)))),
                         file);
        // Save again after a review change: the run folders are not written again.
        const QString firstModel = m_dir.filePath(QStringLiteral("study_runs/run-001/output.ml"));
        const QDateTime written = QFileInfo(firstModel).lastModified();
        QTest::qWait(20);
        ReviewDecisions more = decisions;
        more.setDecision(1, {ReviewVerdict::Flagged, QString()});
        remesh->setDecisions(more);
        QVERIFY(window->isWindowModified());
        remesh->setDecisions(decisions);
        QVERIFY(project->save());
        QVERIFY(!window->isWindowModified());
        QCOMPARE(QFileInfo(firstModel).lastModified(), written);

        std::vector<Figures> before;
        for (const auto &run : project->runs())
            before.push_back(figuresOf(run));
        const LedgerRecord lastRecord = project->runs()[1].outcome.ledger->back();
        const std::size_t shownTriangles = project->runs()[1].outcome.output->triangleCount();
        const std::size_t shownVertices = project->runs()[1].outcome.output->vertices.size();

        // Saved: closing asks nothing.
        QVERIFY(window->close());
        QCOMPARE(asked, 0);
        window.reset();

        auto reopened = newWindow(&asked);
        QVERIFY(QTest::qWaitForWindowExposed(reopened.get()));
        ProjectWorkflow *again = reopened->projectWorkflow();
        QSignalSpy done(again, &ProjectWorkflow::projectOpened);
        QElapsedTimer timer;
        timer.start();
        reopened->openFile(m_project); // by extension, as --open and a dropped file do
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY2(done.first().first().toBool(), qPrintable(allMessages(*reopened)));
        qInfo("project reopened in %lld ms", timer.elapsed());
        QCOMPARE(reopened->remeshWorkflow()->controller()->runCount(), 0); // no engine run
        QCOMPARE(again->runs().size(), std::size_t(2));
        QCOMPARE(again->shownRun(), 1);
        QVERIFY(!reopened->isWindowModified());
        for (std::size_t i = 0; i < 2; ++i) {
            const Figures after = figuresOf(again->runs()[i]);
            QCOMPARE(after.sites, before[i].sites);
            QCOMPARE(after.vertices, before[i].vertices);
            QCOMPARE(after.triangles, before[i].triangles);
            QCOMPARE(after.records, before[i].records);
            QCOMPARE(after.valid, before[i].valid);
            QCOMPARE(after.hausdorff, before[i].hausdorff);
            QCOMPARE(after.meanQ, before[i].meanQ);
            QCOMPARE(after.paramSites, before[i].paramSites);
            QCOMPARE(after.iterations, before[i].iterations);
            // The sizing field's figures come back from the report, not as zeros.
            QVERIFY(before[i].sizedSites > 0 && before[i].smallestSize > 0.0);
            QCOMPARE(after.sizedSites, before[i].sizedSites);
            QCOMPARE(after.smallestSize, before[i].smallestSize);
            QCOMPARE(after.pocketsOpened, before[i].pocketsOpened);
        }
        QCOMPARE(again->runs()[1].decisions, decisions);
        QVERIFY(again->runs()[0].decisions.isEmpty());
        QCOMPARE(reopened->remeshWorkflow()->decisions(), decisions);
        const auto &shown = reopened->outputScene()->model();
        QVERIFY(shown);
        QCOMPARE(shown->triangleCount(), shownTriangles);
        QCOMPARE(shown->vertices.size(), shownVertices);
        QCOMPARE(reopened->remeshWorkflow()->ledgerPanel()->tableModel()->rowCount(),
                 int(before[1].records));
        QCOMPARE(again->runsPanel()->table()->rowCount(), 2);
        double position[3];
        reopened->view()->renderer()->GetActiveCamera()->GetPosition(position);
        for (int i = 0; i < 3; ++i)
            QVERIFY(qAbs(position[i] - savedPosition[i]) < 1e-6 * (1.0 + qAbs(savedPosition[i])));
        // The ledger read back is the one written.
        const LedgerRecord &readBack = again->runs()[1].outcome.ledger->back();
        QCOMPARE(readBack.kind, lastRecord.kind);
        QCOMPARE(readBack.note, lastRecord.note);
        QCOMPARE(readBack.position, lastRecord.position);
        QCOMPARE(readBack.inputs.size(), lastRecord.inputs.size());
        // A run choice is a change to save.
        again->chooseRun(0);
        QVERIFY(reopened->isWindowModified());
        reopened->workbench()->undoStack()->undo();
        QCOMPARE(again->shownRun(), 1);
        QCOMPARE(asked, 0);
    }

    // Compare…: run 1 (150 sites) in the input view, run 2 (300 sites) in the output view, each
    // view titled with its run; the input model stays the one remeshed; undo, Input vs Output.
    void twoRunsSideBySide()
    {
        int asked = 0;
        auto window = newWindow(&asked);
        QVERIFY(QTest::qWaitForWindowExposed(window.get()));
        QSignalSpy opened(window->openWorkflow(), &OpenWorkflow::finished);
        window->openFile(m_input);
        QVERIFY(opened.wait(kTimeoutMs));
        QVERIFY(waitForRemesh(*window, 150));
        QVERIFY(waitForRemesh(*window, 300));
        ProjectWorkflow *project = window->projectWorkflow();
        QUndoStack *undo = window->workbench()->undoStack();
        const auto input = window->workbench()->model();
        const auto runA = project->runs()[0].outcome.output;
        const auto runB = project->runs()[1].outcome.output;
        QVERIFY(runA->triangleCount() != runB->triangleCount());
        QVERIFY(runA->triangleCount() != input->triangleCount());
        auto *inputTitle = window->findChild<QLabel *>(QStringLiteral("InputViewTitle"));
        auto *outputTitle = window->findChild<QLabel *>(QStringLiteral("OutputViewTitle"));
        QVERIFY(inputTitle && outputTitle);
        RunsPanel *panel = project->runsPanel();
        QVERIFY(panel->compareButton()->isEnabled());
        QVERIFY(!panel->inputButton()->isEnabled());
        QCOMPARE(project->comparedRun(), -1);

        // Compare… through its dialog: the run before the one shown goes to the input view.
        QString dialogShot;
        QTimer::singleShot(300, window.get(), [&dialogShot] {
            auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            dialogShot = QStringLiteral(STRATAMESH_SCREENSHOT_DIR) + "/project_compare_dialog.png";
            QDir().mkpath(QStringLiteral(STRATAMESH_SCREENSHOT_DIR));
            dialog->grab().save(dialogShot);
            dialog->accept();
        });
        panel->compareButton()->click();
        QVERIFY(!dialogShot.isEmpty());
        QCOMPARE(project->comparedRun(), 0);
        QCOMPARE(project->shownRun(), 1);
        undo->undo();
        QCOMPARE(project->comparedRun(), -1);

        QVERIFY(!project->compareRuns(1, 1));
        QVERIFY(!project->compareRuns(0, 2));
        const int before = undo->index();
        QVERIFY(project->compareRuns(0, 1));
        QCOMPARE(undo->index(), before + 1);
        QCOMPARE(project->comparedRun(), 0);
        QCOMPARE(project->shownRun(), 1);
        QCOMPARE(window->scene()->model(), runA);
        QCOMPARE(window->scene()->model()->triangleCount(), runA->triangleCount());
        QCOMPARE(window->outputScene()->model(), runB);
        QCOMPARE(window->workbench()->model(), input); // what Remesh… works on
        const QString trianglesA = QString::number(runA->triangleCount());
        const QString trianglesB = QString::number(runB->triangleCount());
        QVERIFY2(inputTitle->text().startsWith(QStringLiteral("Run 1: "))
                     && inputTitle->text().contains(trianglesA),
                 qPrintable(inputTitle->text()));
        QVERIFY2(outputTitle->text().startsWith(QStringLiteral("Run 2: "))
                     && outputTitle->text().contains(trianglesB),
                 qPrintable(outputTitle->text()));
        QVERIFY(panel->inputButton()->isEnabled());
        // Input vs Output compares the two runs shown, with the figures each was made with.
        const ComparisonTable *table = window->findChild<ComparisonTable *>();
        QVERIFY(table && table->hasComparison());
        const auto triangles = [&](ComparisonTable::Column c) {
            return QLocale().toUInt(table->cellText(ComparisonTable::TrianglesRow, c));
        };
        QCOMPARE(table->columnName(ComparisonTable::InputColumn), QStringLiteral("Run 1"));
        QCOMPARE(table->columnName(ComparisonTable::OutputColumn), QStringLiteral("Run 2"));
        QCOMPARE(std::size_t(triangles(ComparisonTable::InputColumn)), runA->triangleCount());
        QCOMPARE(std::size_t(triangles(ComparisonTable::OutputColumn)), runB->triangleCount());
        QVERIFY(table->cellText(ComparisonTable::HausdorffRow, ComparisonTable::InputColumn)
                != QStringLiteral("—"));
        QVERIFY(panel->table()->item(0, 0)->text().startsWith(QStringLiteral("◀")));
        QVERIFY(panel->table()->item(1, 0)->text().startsWith(QStringLiteral("▶")));
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        project->runsDock()->raise();
        QTest::qWait(200);
        QVERIFY(saveWindowScreenshot(window.get(), shots + "/project_compare.png"));

        // Undo: Input vs Output again, the run shown kept.
        undo->undo();
        QCOMPARE(project->comparedRun(), -1);
        QCOMPARE(project->shownRun(), 1);
        QCOMPARE(window->scene()->model(), input);
        QCOMPARE(window->scene()->model()->triangleCount(), input->triangleCount());
        QCOMPARE(window->outputScene()->model(), runB);
        QVERIFY2(inputTitle->text().startsWith(QStringLiteral("Input: ")),
                 qPrintable(inputTitle->text()));
        QVERIFY(!panel->inputButton()->isEnabled());
        QCOMPARE(table->columnName(ComparisonTable::InputColumn), QStringLiteral("Input"));
        QCOMPARE(std::size_t(triangles(ComparisonTable::InputColumn)), input->triangleCount());
        QCOMPARE(std::size_t(triangles(ComparisonTable::OutputColumn)), runB->triangleCount());
        QCOMPARE(table->cellText(ComparisonTable::HausdorffRow, ComparisonTable::InputColumn),
                 QStringLiteral("—"));
        undo->redo();
        QCOMPARE(window->scene()->model(), runA);
        QVERIFY(inputTitle->text().startsWith(QStringLiteral("Run 1: ")));

        // Reversed: run 2 on the left, run 1 on the right; then the button back to the input.
        QVERIFY(project->compareRuns(1, 0));
        QCOMPARE(window->scene()->model(), runB);
        QCOMPARE(window->outputScene()->model(), runA);
        QVERIFY(outputTitle->text().startsWith(QStringLiteral("Run 1: ")));
        QCOMPARE(table->columnName(ComparisonTable::InputColumn), QStringLiteral("Run 2"));
        QCOMPARE(std::size_t(triangles(ComparisonTable::InputColumn)), runB->triangleCount());
        QCOMPARE(std::size_t(triangles(ComparisonTable::OutputColumn)), runA->triangleCount());
        panel->inputButton()->click();
        QCOMPARE(project->comparedRun(), -1);
        QCOMPARE(window->scene()->model(), input);
        QCOMPARE(window->outputScene()->model(), runA);
        undo->undo();
        QCOMPARE(window->scene()->model(), runB);

        // A row chosen in the table: that run beside the input model.
        project->chooseRun(1);
        QCOMPARE(project->comparedRun(), -1);
        QCOMPARE(project->shownRun(), 1);
        QCOMPARE(window->scene()->model(), input);

        // A new run is seen against the input, even when made while comparing.
        QVERIFY(project->compareRuns(0, 1));
        QVERIFY(waitForRemesh(*window, 200));
        QCOMPARE(project->comparedRun(), -1);
        QCOMPARE(project->shownRun(), 2);
        QCOMPARE(window->scene()->model(), input);
        QCOMPARE(asked, 0);
    }

    // The bundled sample has no file: its project says so and reopens it.
    void sampleProject()
    {
        int asked = 0;
        auto window = newWindow(&asked);
        QSignalSpy opened(window->openWorkflow(), &OpenWorkflow::finished);
        window->openSample();
        QVERIFY(opened.wait(kTimeoutMs));
        QVERIFY(waitForRemesh(*window, 150));
        const QString path = m_dir.filePath(QStringLiteral("sample.smproj"));
        QVERIFY(window->projectWorkflow()->saveProject(path));
        const std::size_t triangles = window->outputScene()->model()->triangleCount();
        QSignalSpy done(window->projectWorkflow(), &ProjectWorkflow::projectOpened);
        QVERIFY(window->projectWorkflow()->openProject(path));
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY(done.first().first().toBool());
        QVERIFY(window->workbench()->modelPath().isEmpty());
        QCOMPARE(window->projectWorkflow()->runs().size(), std::size_t(1));
        QCOMPARE(window->outputScene()->model()->triangleCount(), triangles);
        QCOMPARE(window->remeshWorkflow()->controller()->runCount(), 1); // the one before saving
        QCOMPARE(asked, 0);
    }

    void movedInputIsLocated()
    {
        const QString moved = m_dir.filePath(QStringLiteral("elsewhere/modelA1.ml"));
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("elsewhere")));
        QVERIFY(QFile::rename(m_input, moved));
        int asked = 0;
        auto window = newWindow(&asked);
        ProjectWorkflow *project = window->projectWorkflow();
        QString missingAsked;
        project->setLocate([&](const QString &missing) {
            missingAsked = missing;
            return QString();
        });
        QVERIFY(!project->openProject(m_project));
        QCOMPARE(QFileInfo(missingAsked).fileName(), QStringLiteral("modelA1.ml"));
        const QString messages = allMessages(*window);
        QVERIFY2(messages.contains(QStringLiteral("input model")), qPrintable(messages));
        QVERIFY2(messages.contains(QStringLiteral("missing")), qPrintable(messages));
        QVERIFY(project->runs().empty());

        project->setLocate([&](const QString &) { return moved; });
        QSignalSpy done(project, &ProjectWorkflow::projectOpened);
        QVERIFY(project->openProject(m_project));
        QVERIFY(done.wait(kTimeoutMs));
        QVERIFY(done.first().first().toBool());
        QCOMPARE(project->runs().size(), std::size_t(2));
        QCOMPARE(window->workbench()->modelPath(), QFileInfo(moved).absoluteFilePath());
        QVERIFY(window->isWindowModified()); // the new place is saved with the project
        QVERIFY(project->saveProject(m_project));
        // The project now names the new place: the tests below open it from there.
    }

    void movedRunsFolderIsRefused()
    {
        const QString runs = m_dir.filePath(QStringLiteral("study_runs"));
        const QString away = m_dir.filePath(QStringLiteral("away_runs"));
        QVERIFY(QFile::rename(runs, away));
        int asked = 0;
        auto window = newWindow(&asked);
        QVERIFY(!window->projectWorkflow()->openProject(m_project));
        const QString messages = allMessages(*window);
        QVERIFY2(messages.contains(QStringLiteral("study_runs")), qPrintable(messages));
        QVERIFY2(messages.contains(QStringLiteral("moved")), qPrintable(messages));
        QVERIFY(QFile::rename(away, runs));
    }

    void newerSchemaIsRefused()
    {
        const QString path = m_dir.filePath(QStringLiteral("future.smproj"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"schema": 99, "input": {"path": "models/modelA1.ml"}, "runs": []})");
        file.close();
        int asked = 0;
        auto window = newWindow(&asked);
        QVERIFY(!window->projectWorkflow()->openProject(path));
        const QString messages = allMessages(*window);
        QVERIFY2(messages.contains(QStringLiteral("schema 99")), qPrintable(messages));
        QVERIFY2(messages.contains(QStringLiteral("schema 2")), qPrintable(messages));
        QVERIFY(!window->workbench()->model());
    }

    void malformedJsonIsRefused()
    {
        const QString path = m_dir.filePath(QStringLiteral("broken.smproj"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"schema": 1, "runs": [)");
        file.close();
        int asked = 0;
        auto window = newWindow(&asked);
        QVERIFY(!window->projectWorkflow()->openProject(path));
        QCOMPARE(window->messagePanel()->count(Message::Severity::Error), 1);
        const Message error = window->messagePanel()->message(0);
        QVERIFY2(error.text.contains(QStringLiteral("not valid JSON")), qPrintable(error.text));
        QVERIFY2(error.file.endsWith(QStringLiteral("broken.smproj")), qPrintable(error.file));
    }

private:
    QTemporaryDir m_dir;
    QString m_input;
    QString m_project;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiProject test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_gui_project.moc"
