// File > Open Study…: a study run by stratamesh-cli opens as a table (sortable, filterable), its
// charts have one line per model, and a double-click shows a task's input and output side by
// side with its ledger — read from the task folder, not recomputed.
#include "cli_runner.h"
#include "image_compare.h"
#include "ledger_panel.h"
#include "ledger_table_model.h"
#include "main_window.h"
#include "model_scene.h"
#include "study_window.h"
#include "study_workflow.h"
#include "task_result_window.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"

#include <QApplication>
#include <QChartView>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLineEdit>
#include <QLineSeries>
#include <QMenu>
#include <QMenuBar>
#include <QSortFilterProxyModel>
#include <QSurfaceFormat>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::test;

class TestGuiStudy : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        for (const char *name : {"thin", "thick"}) {
            const CliRun made =
                runCli({"synthetic", "layered", "--horizons", name == QString("thin") ? "2" : "3",
                        "--edge-length", "80", "-o", m_dir.filePath(QString(name) + ".ml")});
            QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        }
        QFile study(m_dir.filePath("gui.smstudy"));
        QVERIFY(study.open(QIODevice::WriteOnly));
        study.write(R"({"schema_version": 1, "name": "gui sweep", "models": ["*.ml"],
            "steps": ["remesh"], "grid": {"remesh": {"sites": [80, 120, 160]}},
            "output": "out"})");
        study.close();
        const CliRun run = runCli({"study", m_dir.filePath("gui.smstudy"), "--run", "--jobs", "2"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    }

    void tableChartsAndTaskView()
    {
        StudyWindow window;
        window.openStudy(m_dir.filePath("gui.smstudy"));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.table()->model()->rowCount(), 6);

        // Sorting by the sites column puts 80 first even though "120" < "80" as text.
        const QAbstractItemModel *model = window.table()->model();
        int sitesColumn = -1;
        for (int c = 0; c < model->columnCount(); ++c)
            if (model->headerData(c, Qt::Horizontal).toString() == "remesh.sites")
                sitesColumn = c;
        QVERIFY(sitesColumn >= 0);
        window.table()->sortByColumn(sitesColumn, Qt::DescendingOrder);
        QCOMPARE(model->index(0, sitesColumn).data().toDouble(), 160.0);
        QCOMPARE(model->index(5, sitesColumn).data().toDouble(), 80.0);

        window.filterEdit()->setText("thin.ml");
        QCOMPARE(model->rowCount(), 3);
        window.filterEdit()->clear();
        QCOMPARE(model->rowCount(), 6);

        // One line per model, one point per resolution, for quality and for triangles.
        for (QChartView *view : {window.qualityChart(), window.countChart()}) {
            const QList<QAbstractSeries *> series = view->chart()->series();
            QCOMPARE(series.size(), 2);
            for (QAbstractSeries *s : series)
                QCOMPARE(static_cast<QLineSeries *>(s)->count(), 3);
        }
        const QImage charts = grabWindow(&window);
        QVERIFY(saturatedPixels(charts) > 500); // the coloured lines of the charts

        // Double-click the first row: the task's input and output, with the report's ledger.
        window.table()->sortByColumn(0, Qt::AscendingOrder);
        const QRect cell = window.table()->visualRect(model->index(0, 0));
        // An item view takes a double-click only after the press of the first click.
        QTest::mouseClick(window.table()->viewport(), Qt::LeftButton, {}, cell.center());
        QTest::mouseDClick(window.table()->viewport(), Qt::LeftButton, {}, cell.center());
        QVERIFY(window.taskWindow());
        QVERIFY(QTest::qWaitForWindowExposed(window.taskWindow()));
        TaskResultWindow *task = window.taskWindow();
        QVERIFY(task->inputScene()->model());
        QVERIFY(task->outputScene()->model());
        QVERIFY(task->inputScene()->surfaceActorCount() > 0);
        QVERIFY(task->outputScene()->surfaceActorCount() > 0);
        QVERIFY(task->windowTitle().contains("Task 0"));

        QFile table(m_dir.filePath("out/study.json"));
        QVERIFY(table.open(QIODevice::ReadOnly));
        const QJsonObject first =
            QJsonDocument::fromJson(table.readAll()).object().value("rows").toArray()[0].toObject();
        QCOMPARE(first.value("task").toInt(), 0);
        QFile report(m_dir.filePath("out/" + first.value("folder").toString() + "/remesh.json"));
        QVERIFY(report.open(QIODevice::ReadOnly));
        const int records =
            QJsonDocument::fromJson(report.readAll()).object().value("ledger").toArray().size();
        QCOMPARE(task->ledgerPanel()->tableModel()->rowCount(), records);

        QTest::qWait(300);
        const QImage views = grabWindow(task);
        QVERIFY(saturatedPixels(views) > 2000); // surfaces coloured by feature in both views
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        QVERIFY(saveWindowScreenshot(&window, shots + "/study_window.png"));
        QVERIFY(saveWindowScreenshot(task, shots + "/study_task.png"));
    }

    void fileMenuOpensTheStudy()
    {
        MainWindow window;
        QVERIFY(window.studyWorkflow()->openAction());
        QVERIFY(!window.studyWorkflow()->openAction()->text().isEmpty());
        QVERIFY(window.menuBar()->actions().first()->menu()->actions().contains(
            window.studyWorkflow()->openAction()));
        window.studyWorkflow()->openStudy(m_dir.filePath("out/study.json"));
        QVERIFY(window.studyWorkflow()->studyWindow());
        QVERIFY(QTest::qWaitForWindowExposed(window.studyWorkflow()->studyWindow()));
        QCOMPARE(window.studyWorkflow()->studyWindow()->table()->model()->rowCount(), 6);
    }

    void aStudyWithoutATableSaysSo()
    {
        StudyWindow window;
        QVERIFY_THROWS_EXCEPTION(std::exception, window.openStudy(m_dir.filePath("nothing.json")));
    }

private:
    QTemporaryDir m_dir;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    TestGuiStudy test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_study.moc"
