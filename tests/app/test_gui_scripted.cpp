// Scripted use of the GUI (issue 17): `stratamesh --run … --colour-by … --save-project …
// --screenshot …` does the steps in order and writes a project and a picture that shows the
// models; a failed step exits non-zero naming it; and the main window after each workflow step
// (open, complexity, remesh, review, tetmesh, hybrid, colour by quality, model tree) is saved
// under build/screenshots for the README.
#include "support/test_data.h"
#include "widgets/image_compare.h"

#include "complexity_workflow.h"
#include "gui_options.h"
#include "hybrid_workflow.h"
#include "main_window.h"
#include "model_tree_model.h"
#include "model_tree_panel.h"
#include "model_tree_workflow.h"
#include "open_workflow.h"
#include "remesh_workflow.h"
#include "review_decisions.h"
#include "tetmesh_workflow.h"
#include "translations.h"
#include "view_workflow.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

constexpr int kRunTimeoutMs = 240000;

// Coloured surfaces in the picture, not only the grey window frame: in each half, where the
// input and the output views are.
bool showsModels(const QImage &image, double share, QString &why)
{
    const int half = image.width() / 2;
    const QImage left = image.copy(0, 0, half, image.height()),
                 right = image.copy(half, 0, image.width() - half, image.height());
    const int l = test::saturatedPixels(left), r = test::saturatedPixels(right);
    why = QStringLiteral("%1x%2, saturated pixels left %3, right %4")
              .arg(image.width())
              .arg(image.height())
              .arg(l)
              .arg(r);
    const double area = double(half) * image.height();
    return l > share * area && r > share * area;
}

} // namespace

class TestGuiScripted : public QObject {
    Q_OBJECT
private slots:
    void stepsAreReadInOrder()
    {
        GuiOptions options;
        int exitCode = -1;
        const QStringList args = {QStringLiteral("stratamesh"),   QStringLiteral("--run"),
                                  QStringLiteral("complexity"),   QStringLiteral("--cells"),
                                  QStringLiteral("500"),          QStringLiteral("--remesh-sites"),
                                  QStringLiteral("800"),          QStringLiteral("--run=remesh"),
                                  QStringLiteral("--sites=1000"), QStringLiteral("--run"),
                                  QStringLiteral("tetmesh"),      QStringLiteral("--colour-by"),
                                  QStringLiteral("quality"),      QStringLiteral("--save-project"),
                                  QStringLiteral("p.smproj")};
        QVERIFY(parseGuiOptions(args, options, exitCode));
        using Kind = ScriptStep::Kind;
        QCOMPARE(int(options.steps.size()), 6);
        QCOMPARE(options.steps[0].kind, Kind::Complexity);
        QCOMPARE(options.steps[0].count, 500);
        QCOMPARE(options.steps[1].kind, Kind::Remesh);
        QCOMPARE(options.steps[1].count, 800);
        QCOMPARE(options.steps[2].kind, Kind::Remesh);
        QCOMPARE(options.steps[2].count, 1000);
        QCOMPARE(options.steps[3].kind, Kind::Tetmesh);
        QCOMPARE(options.steps[4].kind, Kind::ColourBy);
        QCOMPARE(options.steps[4].value, QStringLiteral("quality"));
        QCOMPARE(options.steps[5].kind, Kind::SaveProject);
        QCOMPARE(describeStep(options.steps[2]), QStringLiteral("--run remesh --sites 1000"));
    }

    void badStepsAreRefused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("unknown step") << QStringList{QStringLiteral("--run"), QStringLiteral("x")};
        QTest::newRow("sites alone") << QStringList{QStringLiteral("--sites"), QStringLiteral("5")};
        QTest::newRow("cells after remesh")
            << QStringList{QStringLiteral("--run"), QStringLiteral("remesh"),
                           QStringLiteral("--cells"), QStringLiteral("300")};
        QTest::newRow("sites out of range")
            << QStringList{QStringLiteral("--run"), QStringLiteral("remesh"),
                           QStringLiteral("--sites"), QStringLiteral("0")};
        QTest::newRow("unknown colouring")
            << QStringList{QStringLiteral("--colour-by"), QStringLiteral("age")};
    }

    void badStepsAreRefused()
    {
        QFETCH(QStringList, args);
        GuiOptions options;
        int exitCode = -1;
        QVERIFY(
            !parseGuiOptions(QStringList{QStringLiteral("stratamesh")} + args, options, exitCode));
        QCOMPARE(exitCode, 2);
    }

    void scriptedRunWritesProjectAndPicture()
    {
        STRATAMESH_REQUIRE_DATA(model, "modelA1.ml");
        QTemporaryDir dir;
        const QString project = dir.filePath(QStringLiteral("P.smproj"));
        const QString png = dir.filePath(QStringLiteral("S.png"));
        QProcess process;
        process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        QElapsedTimer clock;
        clock.start();
        process.start(QStringLiteral(STRATAMESH_GUI_PATH),
                      {QStringLiteral("--open"), model, QStringLiteral("--run"),
                       QStringLiteral("complexity"), QStringLiteral("--cells"),
                       QStringLiteral("300"), QStringLiteral("--run"), QStringLiteral("remesh"),
                       QStringLiteral("--sites"), QStringLiteral("300"), QStringLiteral("--run"),
                       QStringLiteral("tetmesh"), QStringLiteral("--colour-by"),
                       QStringLiteral("quality"), QStringLiteral("--save-project"), project,
                       QStringLiteral("--screenshot"), png});
        QVERIFY(process.waitForFinished(kRunTimeoutMs));
        qInfo("scripted run: %.1f s", clock.elapsed() / 1000.0);
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 0);
        QVERIFY(QFileInfo::exists(project));

        QProcess cli;
        cli.start(QStringLiteral(STRATAMESH_CLI_PATH), {QStringLiteral("project"), project});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const QJsonObject listing = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
        const QJsonArray runs = listing.value(QStringLiteral("runs")).toArray();
        QCOMPARE(runs.size(), 1);
        // The sites asked for, and at least as many in the end (refinement rounds may add some).
        const QJsonObject run = runs.first().toObject();
        QCOMPARE(run.value(QStringLiteral("parameters"))
                     .toObject()
                     .value(QStringLiteral("sites"))
                     .toInt(),
                 300);
        QVERIFY(run.value(QStringLiteral("sites")).toInt() >= 300);
        QVERIFY(run.value(QStringLiteral("folder_found")).toBool());

        const QImage image(png);
        QVERIFY(!image.isNull());
        QString why;
        const bool shown = showsModels(image, 0.04, why);
        qInfo("%s", qPrintable(why));
        QVERIFY2(shown, qPrintable(why));
    }

    // Without a remesh there is no other model to measure the distance to: the step fails, the
    // screenshot is still written, and the status and message name the step.
    void failedStepExitsWithThree()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("S.png"));
        QProcess process;
        process.start(QStringLiteral(STRATAMESH_GUI_PATH),
                      {QStringLiteral("--colour-by"), QStringLiteral("distance"),
                       QStringLiteral("--screenshot"), png});
        QVERIFY(process.waitForFinished(kRunTimeoutMs));
        QCOMPARE(process.exitCode(), 3);
        const QString err = QString::fromLocal8Bit(process.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("step 1 (--colour-by distance)")), qPrintable(err));
        QVERIFY(!QImage(png).isNull());
    }

    void screenshotsOfEachStep()
    {
        STRATAMESH_REQUIRE_DATA(model, "modelA1.ml");
        const QString folder = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QVERIFY(QDir().mkpath(folder));
        MainWindow window;
        window.resize(1500, 950);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QImage previous;
        int number = 0;
        auto shoot = [&](const char *name) {
            QTest::qWait(300); // the docks laid out, the views drawn
            const QImage image = grabWindow(&window);
            const QString path =
                QStringLiteral("%1/step_%2_%3.png").arg(folder).arg(++number).arg(name);
            QVERIFY(saveWindowScreenshot(&window, path));
            QString why;
            const bool shown = showsModels(image, 0.02, why);
            qInfo("%s: %s", qPrintable(path), qPrintable(why));
            QVERIFY2(shown, qPrintable(why));
            if (!previous.isNull()) {
                const int changed = test::differingPixels(image, previous, 6);
                QVERIFY2(changed > image.width() * image.height() / 200,
                         qPrintable(QStringLiteral("%1 changed %2 pixels").arg(name).arg(changed)));
            }
            previous = image;
        };
        auto await = [&](Workflow *workflow, auto begin) {
            QSignalSpy finished(workflow, &Workflow::finished);
            if (!begin())
                return false;
            return finished.wait(kRunTimeoutMs) && finished.first().first().toBool();
        };

        QVERIFY(await(window.openWorkflow(), [&] {
            window.openFile(model);
            return true;
        }));
        shoot("open");
        if (QTest::currentTestFailed())
            return;
        ComplexityParams complexity;
        complexity.cells = {300};
        QVERIFY(await(window.complexityWorkflow(),
                      [&] { return window.complexityWorkflow()->start(complexity); }));
        shoot("complexity");
        if (QTest::currentTestFailed())
            return;
        RemeshParams remesh;
        remesh.sites = 300;
        QVERIFY(
            await(window.remeshWorkflow(), [&] { return window.remeshWorkflow()->start(remesh); }));
        shoot("remesh");
        if (QTest::currentTestFailed())
            return;
        // The Review tab in use: a record accepted with a note, shown in both views.
        window.remeshWorkflow()->review(0, {ReviewVerdict::Accepted, QStringLiteral("fault kept")});
        window.remeshWorkflow()->showLedgerRecord(0);
        if (auto *dock = window.findChild<QDockWidget *>(QStringLiteral("ReviewDock")))
            dock->raise();
        shoot("review");
        if (QTest::currentTestFailed())
            return;
        QVERIFY(await(window.tetmeshWorkflow(),
                      [&] { return window.tetmeshWorkflow()->start(TetgenParams(), true); }));
        shoot("tetmesh");
        if (QTest::currentTestFailed())
            return;
        HybridParams hybrid;
        hybrid.sites = 300;
        QVERIFY(
            await(window.hybridWorkflow(), [&] { return window.hybridWorkflow()->start(hybrid); }));
        shoot("hybrid");
        if (QTest::currentTestFailed())
            return;
        // Back to the surfaces (a remesh takes the output view back), coloured by Q.
        QVERIFY(
            await(window.remeshWorkflow(), [&] { return window.remeshWorkflow()->start(remesh); }));
        window.viewWorkflow()->chooseColouring(Colouring::Quality);
        shoot("quality");
        if (QTest::currentTestFailed())
            return;
        window.modelTreeWorkflow()->dock()->show();
        window.modelTreeWorkflow()->dock()->raise();
        // A surface chosen in the tree is highlighted in both views.
        window.modelTreeWorkflow()->panel()->selectEntity(ModelTreeModel::Kind::Surface, 0);
        shoot("model_tree");
    }
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiScripted test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_scripted.moc"
