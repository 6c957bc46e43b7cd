// File > Open Recent and the window's layout kept in the settings (issue 17): two models opened
// are listed most recent first, a removed one shows disabled with "File not found", the list and
// the dock layout survive a new window reading the same settings, Clear Menu empties the list.
// Disabled actions say why in their tooltip. The settings live in a temporary folder
// (STRATAMESH_SETTINGS_DIR): never the developer's.
#include "main_window.h"
#include "open_workflow.h"
#include "project_workflow.h"
#include "recent_files.h"
#include "remesh_workflow.h"
#include "support/test_data.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;

bool openAndWait(MainWindow &window, const QString &path)
{
    QSignalSpy finished(window.openWorkflow(), &OpenWorkflow::finished);
    window.openFile(path);
    return finished.wait(kTimeoutMs) && finished.first().first().toBool();
}

// The file entries of the menu, as shown: its actions before the separator.
QList<QAction *> entries(RecentFiles &recent)
{
    recent.refresh();
    QList<QAction *> files;
    for (QAction *action : recent.menu()->actions()) {
        if (action->isSeparator())
            break;
        files.append(action);
    }
    return files;
}

} // namespace

class TestGuiRecent : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QVERIFY(m_settings.isValid());
        QVERIFY(m_models.isValid());
        qputenv("STRATAMESH_SETTINGS_DIR", m_settings.path().toLocal8Bit());
        STRATAMESH_REQUIRE_DATA(a1, "modelA1.ml");
        STRATAMESH_REQUIRE_DATA(cube, "split_cube.ml");
        m_first = m_models.filePath(QStringLiteral("first_A1.ml"));
        m_second = m_models.filePath(QStringLiteral("second_cube.ml"));
        QVERIFY(QFile::copy(a1, m_first));
        QVERIFY(QFile::copy(cube, m_second));
    }

    void listsMostRecentFirstAndSurvivesTheWindow()
    {
        {
            MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            RecentFiles *recent = window.recentFiles();
            QVERIFY(recent->paths().isEmpty()); // a fresh settings folder, not the developer's
            QVERIFY(!recent->clearAction()->isEnabled());

            // The submenu sits in File, right below the Open actions.
            const QList<QAction *> file = window.menuBar()->actions().first()->menu()->actions();
            const qsizetype sample = file.indexOf(window.openWorkflow()->openSampleAction());
            QVERIFY(sample >= 0 && sample + 1 < file.size());
            QCOMPARE(file[sample + 1]->menu(), recent->menu());

            QVERIFY(openAndWait(window, m_first));
            QVERIFY(openAndWait(window, m_second));
            QSignalSpy sampleOpened(window.openWorkflow(), &OpenWorkflow::finished);
            window.openSample(); // no file: not listed
            QVERIFY(sampleOpened.wait(kTimeoutMs));
            QList<QAction *> files = entries(*recent);
            QCOMPARE(files.size(), 2);
            QCOMPARE(files[0]->data().toString(), m_second);
            QCOMPARE(files[1]->data().toString(), m_first);
            QVERIFY(files[0]->text().contains(QStringLiteral("second_cube.ml")));
            QVERIFY(files[0]->isEnabled() && files[1]->isEnabled());
            QVERIFY(recent->clearAction()->isEnabled());

            // Opened again: back on top, not listed twice.
            QVERIFY(openAndWait(window, m_first));
            files = entries(*recent);
            QCOMPARE(files.size(), 2);
            QCOMPARE(files[0]->data().toString(), m_first);

            // An entry opens its file.
            QSignalSpy opened(window.openWorkflow(), &OpenWorkflow::finished);
            files[1]->trigger();
            QVERIFY(opened.wait(kTimeoutMs));
            QCOMPARE(window.workbench()->modelPath(), m_second);

            window.addDockWidget(Qt::LeftDockWidgetArea,
                                 window.findChild<QDockWidget *>(QStringLiteral("MessageDock")));
            window.resize(1100, 700);
            QVERIFY(window.close()); // nothing unsaved: no question
        }

        QVERIFY(QFile::remove(m_first));
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QList<QAction *> files = entries(*again.recentFiles());
        QCOMPARE(files.size(), 2);
        QCOMPARE(files[0]->data().toString(), m_second); // opened last, from the menu
        QCOMPARE(files[1]->data().toString(), m_first);
        QVERIFY(files[0]->isEnabled());
        QVERIFY(!files[1]->isEnabled()); // removed since
        QVERIFY(files[1]->toolTip().startsWith(QStringLiteral("File not found")));
        // The layout came back: the Messages dock where the first window left it.
        auto *messages = again.findChild<QDockWidget *>(QStringLiteral("MessageDock"));
        QCOMPARE(again.dockWidgetArea(messages), Qt::LeftDockWidgetArea);
        QCOMPARE(again.size(), QSize(1100, 700));

        again.recentFiles()->menu()->popup(again.mapToGlobal(QPoint(40, 40)));
        QTest::qWait(200);
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        QVERIFY(saveWindowScreenshot(again.recentFiles()->menu(), shots + "/recent_menu.png"));
        again.recentFiles()->menu()->hide();

        again.recentFiles()->clearAction()->trigger();
        QVERIFY(entries(*again.recentFiles()).isEmpty());
        QVERIFY(again.recentFiles()->paths().isEmpty());
        QVERIFY(!again.recentFiles()->clearAction()->isEnabled());
    }

    void olderLayoutIsIgnored()
    {
        {
            MainWindow window;
            window.saveLayout();
        }
        QSettings settings(QDir(m_settings.path()).filePath(QStringLiteral("StrataMesh.ini")),
                           QSettings::IniFormat);
        QMainWindow other;
        settings.setValue(QStringLiteral("window/state"),
                          other.saveState(MainWindow::kStateVersion - 1));
        settings.sync();
        MainWindow window;
        QVERIFY(!window.restoreLayout());
    }

    // Before a model, Remesh… and the saves are disabled and say why; after, Remesh… is enabled
    // and its tooltip is Qt's again (the action's text), while the save still waits for a result.
    void disabledActionsSayWhy()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        RemeshWorkflow *remesh = window.remeshWorkflow();
        QVERIFY(!remesh->remeshAction()->isEnabled());
        QCOMPARE(remesh->remeshAction()->toolTip(), QStringLiteral("Remesh…: no model open"));
        QCOMPARE(remesh->saveAction()->toolTip(),
                 QStringLiteral("Save Remeshed Model As…: no remeshed model yet"));
        QCOMPARE(window.projectWorkflow()->saveAction()->toolTip(),
                 QStringLiteral("Save Project: no model open"));
        QVERIFY(openAndWait(window, m_second));
        QVERIFY(remesh->remeshAction()->isEnabled());
        QCOMPARE(remesh->remeshAction()->toolTip(), QStringLiteral("Remesh…"));
        QVERIFY(!remesh->saveAction()->isEnabled());
        QCOMPARE(remesh->saveAction()->toolTip(),
                 QStringLiteral("Save Remeshed Model As…: no remeshed model yet"));
        QCOMPARE(window.projectWorkflow()->saveAction()->toolTip(), QStringLiteral("Save Project"));
    }

    // Every disabled entry of every menu says why, with no model and with one: a greyed entry is
    // never a riddle. (Recent files that are gone say so in their own words.)
    void everyDisabledMenuEntrySaysWhy()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const auto unexplained = [&window] {
            QStringList silent;
            std::function<void(const QList<QAction *> &)> visit =
                [&](const QList<QAction *> &list) {
                    for (QAction *a : list) {
                        if (a->menu()) {
                            visit(a->menu()->actions());
                            continue;
                        }
                        if (a->isSeparator() || a->isEnabled() || a->text().isEmpty())
                            continue;
                        QString text = a->text();
                        text.remove(QLatin1Char('&'));
                        if (!a->toolTip().startsWith(text + QStringLiteral(": ")))
                            silent << text + QStringLiteral(" [") + a->toolTip() + QLatin1Char(']');
                    }
                };
            visit(window.menuBar()->actions());
            return silent;
        };
        QStringList silent = unexplained();
        QVERIFY2(silent.isEmpty(), qPrintable(silent.join(QStringLiteral("; "))));
        QVERIFY(openAndWait(window, m_second));
        silent = unexplained();
        QVERIFY2(silent.isEmpty(), qPrintable(silent.join(QStringLiteral("; "))));
    }

    void atMostEightFiles()
    {
        MainWindow window;
        RecentFiles *recent = window.recentFiles();
        recent->clear();
        for (int i = 0; i < 10; ++i)
            recent->add(m_models.filePath(QStringLiteral("m%1.ml").arg(i)));
        const QStringList paths = recent->paths();
        QCOMPARE(paths.size(), RecentFiles::kMaxFiles);
        QCOMPARE(paths.first(), m_models.filePath(QStringLiteral("m9.ml")));
        QCOMPARE(paths.last(), m_models.filePath(QStringLiteral("m2.ml")));
    }

private:
    QTemporaryDir m_settings;
    QTemporaryDir m_models;
    QString m_first;
    QString m_second;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiRecent test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_gui_recent.moc"
