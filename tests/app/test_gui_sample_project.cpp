// The window without a file opens the bundled sample as a project (issue 17, set-up promise):
// the first time it is made (one remesh, saved in the user's data folder); then it is read back
// without remeshing; an unreadable one is made again.
#include "main_window.h"
#include "model_scene.h"
#include "project_file.h"
#include "project_workflow.h"
#include "remesh_controller.h"
#include "remesh_workflow.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

using namespace stratamesh;

namespace {
constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

std::unique_ptr<MainWindow> newWindow()
{
    auto window = std::make_unique<MainWindow>();
    window->resize(1400, 900);
    window->show();
    window->workbench()->setAsk([](const QString &) { return QMessageBox::Discard; });
    return window;
}

bool waitForSampleProject(MainWindow &window)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < kTimeoutMs) {
        if (window.projectWorkflow()->projectPath() == MainWindow::sampleProjectPath()
            && !window.workbench()->isBusy() && !window.isWindowModified())
            return true;
        QTest::qWait(50);
    }
    return false;
}
} // namespace

class TestGuiSampleProject : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        // The user's data folder of a test (~/.qttest/share/…), emptied.
        QStandardPaths::setTestModeEnabled(true);
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        QDir(QFileInfo(MainWindow::sampleProjectPath()).absolutePath()).removeRecursively();
    }

    void firstStartMakesIt()
    {
        auto window = newWindow();
        window->openSampleProject();
        QVERIFY(waitForSampleProject(*window));
        QVERIFY(QFileInfo::exists(MainWindow::sampleProjectPath()));
        QCOMPARE(window->projectWorkflow()->runs().size(), std::size_t(1));
        QCOMPARE(window->remeshWorkflow()->controller()->runCount(), 1);
        QVERIFY(window->workbench()->modelPath().isEmpty()); // the built-in sample model
        QVERIFY(window->outputScene()->model());
        m_triangles = window->outputScene()->model()->triangleCount();
        QVERIFY(m_triangles > 0);
    }

    void laterStartsReadIt()
    {
        auto window = newWindow();
        QSignalSpy opened(window->projectWorkflow(), &ProjectWorkflow::projectOpened);
        window->openSampleProject();
        QVERIFY(opened.wait(kTimeoutMs) && opened.first().first().toBool());
        QCOMPARE(window->projectWorkflow()->runs().size(), std::size_t(1));
        QCOMPARE(window->remeshWorkflow()->controller()->runCount(), 0); // nothing recomputed
        QCOMPARE(window->outputScene()->model()->triangleCount(), m_triangles);
        QVERIFY2(window->windowTitle().startsWith(QLatin1String("sample.smproj (Sample model)")),
                 qPrintable(window->windowTitle()));
        QTest::qWait(200);
        QVERIFY(saveWindowScreenshot(window.get(),
                                     QDir(kShots).filePath(QStringLiteral("sample_project.png"))));
    }

    void unreadableIsMadeAgain()
    {
        QFile file(MainWindow::sampleProjectPath());
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write("{ not json");
        file.close();
        auto window = newWindow();
        window->openSampleProject();
        QVERIFY(waitForSampleProject(*window));
        QCOMPARE(window->remeshWorkflow()->controller()->runCount(), 1);
        QCOMPARE(readProjectFile(MainWindow::sampleProjectPath()).runs.size(), std::size_t(1));
    }

private:
    std::size_t m_triangles = 0;
};

QTEST_MAIN(TestGuiSampleProject)
#include "test_gui_sample_project.moc"
