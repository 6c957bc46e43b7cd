// The Steps dock (issue 17): the workflow in order, each step's buttons the menu actions
// themselves, and each status following what was done (validity, complexity, remesh, volume).
#include "complexity_workflow.h"
#include "export_workflow.h"
#include "gui_fixture.h"
#include "hybrid_workflow.h"
#include "main_window.h"
#include "open_workflow.h"
#include "remesh/surface_remesher.h"
#include "remesh_workflow.h"
#include "step_list.h"
#include "steps_workflow.h"
#include "tetmesh_workflow.h"
#include "window_screenshot.h"

#include <QDir>
#include <QDockWidget>
#include <QSignalSpy>
#include <QToolButton>
#include <QtTest>

using namespace stratamesh;

namespace {
constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
} // namespace

class TestGuiSteps : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void stepsAreInOrderWithTheMenuActions()
    {
        StepList *steps = m_window->stepsWorkflow()->steps();
        QCOMPARE(steps->count(), int(StepsWorkflow::StepCount));
        QVERIFY(steps->titleText(StepsWorkflow::Check).startsWith(QLatin1String("1. Check")));
        QVERIFY(steps->titleText(StepsWorkflow::Export).startsWith(QLatin1String("5. Export")));
        QCOMPARE(steps->actions(StepsWorkflow::Complexity),
                 QList<QAction *>{m_window->complexityWorkflow()->analyseAction()});
        QCOMPARE(steps->actions(StepsWorkflow::Remesh),
                 QList<QAction *>{m_window->remeshWorkflow()->remeshAction()});
        QCOMPARE(steps->actions(StepsWorkflow::Volume),
                 (QList<QAction *>{m_window->tetmeshWorkflow()->tetmeshAction(),
                                   m_window->hybridWorkflow()->hybridAction()}));
        // The buttons are the actions: disabled with them before a model is open.
        const QList<QToolButton *> buttons = steps->findChildren<QToolButton *>();
        QCOMPARE(buttons.size(), 6);
        for (QToolButton *b : buttons)
            QCOMPARE(b->isEnabled(), b->defaultAction()->isEnabled());
        QVERIFY(!steps->isDone(StepsWorkflow::Check));
        QVERIFY(!m_window->remeshWorkflow()->remeshAction()->isEnabled());
    }

    void statusesFollowTheWork()
    {
        QVERIFY(test::openSample(*m_window, kTimeoutMs));
        StepList *steps = m_window->stepsWorkflow()->steps();
        QVERIFY(steps->isDone(StepsWorkflow::Check));
        QVERIFY2(steps->statusText(StepsWorkflow::Check).contains(QLatin1String("no validity")),
                 qPrintable(steps->statusText(StepsWorkflow::Check)));
        QVERIFY(!steps->isDone(StepsWorkflow::Remesh));

        QVERIFY(test::remeshOpenModel(*m_window, 300, 20, kTimeoutMs));
        QVERIFY(steps->isDone(StepsWorkflow::Remesh));
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        const QString status = steps->statusText(StepsWorkflow::Remesh);
        QVERIFY2(status.startsWith(QString::number(outcome->siteCount) + " sites"),
                 qPrintable(status));
        QVERIFY2(status.contains(QString::number(outcome->comparison.output.mesh.triangles)
                                 + " triangles"),
                 qPrintable(status));
        QVERIFY(steps->titleText(StepsWorkflow::Remesh).endsWith(QStringLiteral("✓")));
        QVERIFY(!steps->isDone(StepsWorkflow::Volume));

        // The dock is a tab beside the model tree; shown, it is what the screenshot holds.
        QDockWidget *dock = m_window->stepsWorkflow()->dock();
        dock->show();
        dock->raise();
        QTest::qWait(200);
        QVERIFY(dock->isVisible());
        const QString shot = QDir(kShots).filePath(QStringLiteral("steps.png"));
        QVERIFY(saveWindowScreenshot(m_window.get(), shot));
    }

private:
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(TestGuiSteps)
#include "test_gui_steps.moc"
