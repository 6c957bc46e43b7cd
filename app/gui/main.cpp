// stratamesh: the desktop application.
#include "common/version.h"
#include "gui_options.h"
#include "main_window.h"
#include "open_workflow.h"
#include "project_file.h"
#include "project_workflow.h"
#include "script_runner.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

int main(int argc, char **argv)
{
    // VTK needs a core-profile context; it must be the default before any window exists.
    QSurfaceFormat::setDefaultFormat(stratamesh::VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMesh"));
    QApplication::setOrganizationName(QStringLiteral("StrataMesh"));
    QApplication::setApplicationVersion(QStringLiteral(STRATAMESH_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/stratamesh.png")));

    stratamesh::installTranslations(stratamesh::languageArgument(QApplication::arguments()));
    stratamesh::GuiOptions options;
    int exitCode = 0;
    if (!stratamesh::parseGuiOptions(QApplication::arguments(), options, exitCode))
        return exitCode;

    stratamesh::MainWindow window;
    window.setBoxVisible(options.showBox);
    window.setEdgesVisible(options.showEdges);
    // Exit status: 0, 1 when the image could not be written, 2 when the model could not be opened,
    // 3 when a step failed.
    const auto screenshot = [&](int status) {
        // Let the window lay itself out and the view render once before grabbing.
        QTimer::singleShot(300, &window, [&, status] {
            const bool saved = stratamesh::saveWindowScreenshot(&window, options.screenshotPath);
            if (!saved)
                std::fprintf(stderr, "stratamesh: cannot write %s\n",
                             qPrintable(options.screenshotPath));
            QApplication::exit(!saved ? 1 : status);
        });
    };
    const bool scripted = !options.screenshotPath.isEmpty() || !options.steps.empty();
    stratamesh::ScriptRunner runner(window, options.steps);
    const auto opened = [&](bool ok) {
        if (ok) {
            runner.start();
        } else if (!options.screenshotPath.isEmpty()) {
            screenshot(2);
        } else if (!options.steps.empty()) {
            std::fprintf(stderr, "stratamesh: %s\n",
                         qPrintable(QCoreApplication::translate(
                             "GuiOptions", "the model could not be opened: no step was done.")));
            QApplication::exit(2);
        }
    };
    QObject::connect(&runner, &stratamesh::ScriptRunner::finished, &window, [&](bool ok) {
        if (!ok)
            std::fprintf(stderr, "stratamesh: %s\n", qPrintable(runner.failure()));
        if (!options.screenshotPath.isEmpty())
            screenshot(ok ? 0 : 3);
        else if (!ok)
            QApplication::exit(3);
        // Steps without a screenshot leave the window open on their results.
    });
    const bool project = stratamesh::isProjectFile(options.openPath);
    if (scripted) {
        if (project)
            QObject::connect(window.projectWorkflow(), &stratamesh::ProjectWorkflow::projectOpened,
                             &window, opened, Qt::SingleShotConnection);
        else
            QObject::connect(window.openWorkflow(), &stratamesh::OpenWorkflow::finished, &window,
                             opened, Qt::SingleShotConnection);
    }
    window.show();
    if (options.openPath.isEmpty() && scripted)
        window.openSample(); // scripted steps start from the model alone
    else if (options.openPath.isEmpty())
        window.openSampleProject();
    else if (project) {
        // False when the project cannot be read (no projectOpened() follows).
        if (!window.projectWorkflow()->openProject(options.openPath) && scripted)
            QTimer::singleShot(0, &window, [&] { opened(false); });
    } else {
        window.openFile(options.openPath);
    }
    return app.exec();
}
