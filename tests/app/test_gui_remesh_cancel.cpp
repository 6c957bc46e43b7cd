// Cancel during mesh building, on a real model at the size a geologist asks for (modelA5 at 5000
// sites): the worker returns within 0.5 s of Cancel, the progress the window received never went
// back and named the mesh-building steps, and the previous remesh stays shown.
#include "main_window.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "remesh_controller.h"
#include "remesh_workflow.h"
#include "support/sanitizer.h"
#include "support/test_data.h"

#include <QAction>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>

using namespace stratamesh;

class TestGuiRemeshCancel : public QObject {
    Q_OBJECT
private slots:
    void cancelDuringMeshBuilding();
};

void TestGuiRemeshCancel::cancelDuringMeshBuilding()
{
    STRATAMESH_REQUIRE_DATA(path, "modelA5.ml");
    QLocale::setDefault(QLocale::c());
    MainWindow window;
    window.resize(1200, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy loaded(window.openWorkflow(), &OpenWorkflow::finished);
    window.openFile(path);
    QVERIFY(loaded.wait(120000));
    QVERIFY(loaded.first().first().toBool());

    // A first, quick remesh: the one that must stay after the cancel.
    RemeshParams quick;
    quick.sites = 500;
    quick.iterations = 5;
    quick.refinementRounds = 0;
    QSignalSpy finished(window.remeshWorkflow(), &RemeshWorkflow::finished);
    QVERIFY(window.remeshWorkflow()->start(quick));
    QVERIFY(finished.wait(180000));
    QVERIFY(finished.first().first().toBool());
    QVERIFY(window.remeshWorkflow()->outcome());
    const auto previous = window.remeshWorkflow()->outcome()->output;
    const int previousSites = window.remeshWorkflow()->outcome()->siteCount;
    finished.clear();

    RemeshController *job = window.remeshWorkflow()->controller();
    std::vector<int> percents;
    QStringList stages;
    QElapsedTimer sinceCancel;
    connect(job, &RemeshController::progressChanged, this, [&](int percent, const QString &stage) {
        percents.push_back(percent);
        stages << stage;
        if (!sinceCancel.isValid() && stage.contains(QLatin1String("Mesh building: cell points"))) {
            sinceCancel.start();
            window.remeshWorkflow()->cancelAction()->trigger();
        }
    });
    qint64 stoppedAfter = -1;
    connect(job, &RemeshController::cancelled, this,
            [&] { stoppedAfter = sinceCancel.isValid() ? sinceCancel.elapsed() : -1; });
    RemeshParams big;
    big.sites = 5000;
    QVERIFY(window.remeshWorkflow()->start(big));
    QVERIFY(finished.wait(300000));
    QVERIFY(!finished.first().first().toBool());
    QVERIFY(sinceCancel.isValid());
    qInfo("cancelled at %s; the worker returned %lld ms after Cancel, %zu progress values",
          qPrintable(stages.last()), stoppedAfter, percents.size());
    QVERIFY(stoppedAfter >= 0);
    QVERIFY2(stoppedAfter < 500 * stratamesh::test::kTimeScale,
             qPrintable(QString::number(stoppedAfter)));
    QVERIFY(percents.size() > 5);
    for (std::size_t i = 1; i < percents.size(); ++i)
        QVERIFY2(percents[i] >= percents[i - 1], qPrintable(stages[int(i)]));
    // The CVT came before, and its share of the bar with it.
    QVERIFY(stages.filter(QLatin1String("CVT")).size() > 0);
    QVERIFY(percents.back() >= 30);

    // The previous result stays, and the window is usable again.
    QVERIFY(window.remeshWorkflow()->outcome());
    QCOMPARE(window.remeshWorkflow()->outcome()->output, previous);
    QCOMPARE(window.remeshWorkflow()->outcome()->siteCount, previousSites);
    QCOMPARE(window.outputScene()->model(), previous);
    QVERIFY(!job->isBusy());
    QVERIFY(window.remeshWorkflow()->remeshAction()->isEnabled());
    QVERIFY(!window.remeshWorkflow()->cancelAction()->isEnabled());
}

QTEST_MAIN(TestGuiRemeshCancel)
#include "test_gui_remesh_cancel.moc"
