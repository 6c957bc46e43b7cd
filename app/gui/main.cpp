// stratamesh: the desktop application.
#include "common/version.h"
#include "complexity_workflow.h"
#include "gui_options.h"
#include "ledger_panel.h"
#include "main_window.h"
#include "open_workflow.h"
#include "remesh_workflow.h"
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
    const auto screenshot = [&](bool ok) {
        // Let the window lay itself out and the view render once before grabbing.
        QTimer::singleShot(300, &window, [&, ok] {
            const bool saved = stratamesh::saveWindowScreenshot(&window, options.screenshotPath);
            if (!saved)
                std::fprintf(stderr, "stratamesh: cannot write %s\n",
                             qPrintable(options.screenshotPath));
            QApplication::exit(!saved ? 1 : ok ? 0 : 2);
        });
    };
    if (options.remeshSites > 0) {
        QObject::connect(
            window.openWorkflow(), &stratamesh::OpenWorkflow::finished, &window,
            [&](bool ok) {
                stratamesh::RemeshParams params;
                params.sites = options.remeshSites;
                if (!ok || !window.remeshWorkflow()->start(params)) {
                    if (!options.screenshotPath.isEmpty())
                        screenshot(false);
                }
            },
            Qt::SingleShotConnection);
        if (!options.screenshotPath.isEmpty())
            QObject::connect(
                window.remeshWorkflow(), &stratamesh::RemeshWorkflow::finished, &window,
                [&](bool ok) {
                    if (ok) {
                        window.remeshWorkflow()->ledgerPanel()->selectRow(0);
                        window.resetCamera(); // the whole model, the marked record somewhere in it
                    }
                    screenshot(ok);
                });
    } else if (options.complexityCells > 0) {
        QObject::connect(
            window.openWorkflow(), &stratamesh::OpenWorkflow::finished, &window,
            [&](bool ok) {
                stratamesh::ComplexityParams params;
                params.cells = {options.complexityCells};
                if (!ok || !window.complexityWorkflow()->start(params)) {
                    if (!options.screenshotPath.isEmpty())
                        screenshot(false);
                }
            },
            Qt::SingleShotConnection);
        if (!options.screenshotPath.isEmpty())
            QObject::connect(window.complexityWorkflow(), &stratamesh::ComplexityWorkflow::finished,
                             &window, screenshot);
    } else if (!options.screenshotPath.isEmpty()) {
        QObject::connect(window.openWorkflow(), &stratamesh::OpenWorkflow::finished, &window,
                         screenshot);
    }
    window.show();
    if (options.openPath.isEmpty())
        window.openSample();
    else
        window.openFile(options.openPath);
    return app.exec();
}
