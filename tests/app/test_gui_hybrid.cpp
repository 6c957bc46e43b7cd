// Mesh > Hybrid Mesh… end to end through the real controller on modelA1: the Hybrid Mesh dock
// holds the core's per-type figures, the view draws every cell of the mesh, coloured by type
// (legend) or by min dihedral angle (values within the core's per-type bounds), and the clip
// plane opens it; Cancel during a long run stops the worker and leaves the previous mesh; a save
// writes a .vtu and a .msh that the core's reader reads back with the same cells per type, and a
// wrong extension writes nothing; a whole long run moves the bar forward only, and its longest wait
// between progress updates is printed (it bounds how long a Cancel waits).
#include "widgets/image_compare.h"

#include "hybrid_controller.h"
#include "hybrid_panel.h"
#include "hybrid_workflow.h"
#include "io/mesh_reader.h"
#include "main_window.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "progress_strip.h"
#include "support/test_data.h"
#include "tet_mesh_pair.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <algorithm>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 300000;
constexpr CellType kTypes[] = {CellType::Tet, CellType::Pyramid, CellType::Prism};

HybridParams smallParams()
{
    HybridParams p;
    p.sites = 300;
    return p;
}

} // namespace

class TestGuiHybrid : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QLocale::setDefault(QLocale::c());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1500, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(!m_window->hybridWorkflow()->hybridAction()->isEnabled()); // nothing to mesh yet
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openFile(path);
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY(m_window->hybridWorkflow()->hybridAction()->isEnabled());
        QVERIFY(!m_window->hybridWorkflow()->saveAction()->isEnabled());
    }

    void cleanupTestCase() { m_window.reset(); }

    // The dock and the view show what the core made, cell type by cell type.
    void buildShowsTheMesh()
    {
        HybridWorkflow *hybrid = m_window->hybridWorkflow();
        QSignalSpy finished(hybrid, &HybridWorkflow::finished);
        QSignalSpy progress(hybrid->controller(), &HybridController::progressChanged);
        QVERIFY(hybrid->start(smallParams()));
        QVERIFY(m_window->findChild<ProgressStrip *>()->progressBar()->isVisible());
        QVERIFY(hybrid->cancelAction()->isEnabled());
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(finished.first().first().toBool());
        QVERIFY(progress.size() > 3);
        QVERIFY(!hybrid->cancelAction()->isEnabled());
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);

        const auto &outcome = hybrid->outcome();
        QVERIFY(outcome && outcome->result);
        const VolumeMesh &mesh = outcome->result->mesh;
        QVERIFY(mesh.hasCells());
        QCOMPARE(mesh.cellQuality.size(), mesh.cells.size());
        qInfo("hybrid modelA1 at 300 sites: %zu tets, %zu pyramids, %zu prisms, valid %d",
              mesh.countCells(CellType::Tet), mesh.countCells(CellType::Pyramid),
              mesh.countCells(CellType::Prism), int(outcome->statistics.valid));

        HybridPanel *panel = hybrid->panel();
        QVERIFY(panel->hasResult());
        for (CellType type : kTypes) {
            const std::size_t cells = mesh.countCells(type);
            QCOMPARE(panel->cellText(HybridPanel::CellsRow, type).toULongLong(), qulonglong(cells));
            QCOMPARE(outcome->statistics.byType[std::size_t(type)].cells, cells);
        }
        QCOMPARE(panel->cellText(HybridPanel::SliversRow, CellType::Tet).toULongLong(),
                 qulonglong(outcome->statistics.byType[0].slivers));
        // The mean of the smallest angles lies between the type's smallest and largest angle.
        for (CellType type : kTypes) {
            const TypeQuality &q = outcome->statistics.byType[std::size_t(type)];
            if (q.cells == 0)
                continue;
            const double mean =
                QLocale().toDouble(panel->cellText(HybridPanel::MeanMinDihedralRow, type));
            QVERIFY2(mean >= q.minDihedral - 0.005 && mean <= q.maxDihedral,
                     qPrintable(panel->cellText(HybridPanel::MeanMinDihedralRow, type)));
        }
        // Where the cells come from: the four origins add up to the mesh's cells.
        const HybridStatistics &st = outcome->statistics;
        QCOMPARE(st.segmentDual + st.vertexDual + st.transitionPyramids + st.fillTets,
                 mesh.cells.size());
        QVERIFY(panel->summaryText().contains(QLocale().toString(qulonglong(st.fillTets))));
        QVERIFY(panel->summaryText().contains(QLatin1String("Invalid cells found")));
        QVERIFY(panel->summaryText().contains(QLatin1String("Time:")));
        QVERIFY(panel->isVisible());
        QVERIFY(hybrid->saveAction()->isEnabled());

        // Every cell is drawn in the output view, in place of the surfaces.
        TetMeshScene &scene = hybrid->scenes()->output();
        QCOMPARE(scene.tetCount(), int(mesh.cells.size()));
        for (CellType type : kTypes)
            QCOMPARE(scene.cellCount(type), int(mesh.countCells(type)));
        QVERIFY(!hybrid->scenes()->input().mesh());
        QVERIFY(m_window->outputView()->isVisible());
        QVERIFY(!m_window->outputScene()->isVisible());
        QCOMPARE(scene.colouring(), TetColouring::Type);

        // By quality: the values drawn lie within the core's per-type bounds.
        panel->setColouring(TetColouring::MinDihedral);
        QCOMPARE(scene.colouring(), TetColouring::MinDihedral);
        double low = 180.0, high = 0.0;
        for (CellType type : kTypes) {
            const TypeQuality &q = outcome->statistics.byType[std::size_t(type)];
            if (q.cells > 0) {
                low = std::min(low, q.minDihedral);
                high = std::max(high, q.maxDihedral);
            }
        }
        double range[2];
        QVERIFY(scene.dihedralRange(range));
        QVERIFY2(range[0] >= 0.0 && range[1] <= 180.0 && range[0] <= range[1],
                 qPrintable(QStringLiteral("%1..%2").arg(range[0]).arg(range[1])));
        QVERIFY(range[0] >= low - 1e-9 && range[1] <= high + 1e-9);
        QVERIFY(qFuzzyCompare(range[0], low)); // the worst cell is the dock's minimum
        QTest::qWait(200);
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        QVERIFY(saveWindowScreenshot(m_window.get(), shots + "/hybrid_quality.png"));

        // Clipped half-way, coloured by type: part of the cells, the inside shown.
        panel->setColouring(TetColouring::Type);
        panel->setClip(true, ClipAxis::Y, 0.5);
        QVERIFY(scene.isClipped());
        const int shown = scene.shownTetCount();
        QVERIFY2(shown > 0 && shown < scene.tetCount(),
                 qPrintable(QStringLiteral("%1 of %2").arg(shown).arg(scene.tetCount())));
        QTest::qWait(200);
        const QImage image = m_window->outputView()->grabFramebuffer();
        const int drawn = test::saturatedPixels(image);
        QVERIFY2(drawn > image.width() * image.height() / 20, qPrintable(QString::number(drawn)));
        QVERIFY(saveWindowScreenshot(m_window.get(), shots + "/hybrid_types_clipped.png"));
        panel->setClip(false, ClipAxis::Y, 0.5);
        QCOMPARE(scene.shownTetCount(), scene.tetCount());
    }

    // Cancel at several moments of a long run: the worker returns soon after, the previous mesh
    // stays in the dock and the view.
    void cancelKeepsThePreviousMesh_data()
    {
        QTest::addColumn<int>("delayMs");
        QTest::newRow("early") << 300;
        QTest::newRow("later") << 2500;
        QTest::newRow("late") << 6000;
    }

    void cancelKeepsThePreviousMesh()
    {
        QFETCH(int, delayMs);
        HybridWorkflow *hybrid = m_window->hybridWorkflow();
        QVERIFY(hybrid->outcome());
        const auto previous = hybrid->outcome()->result;
        const QString cells = hybrid->panel()->cellText(HybridPanel::CellsRow, CellType::Tet);

        HybridController *job = hybrid->controller();
        QString lastStage;
        QElapsedTimer sinceCancel;
        qint64 stoppedAfter = -1;
        QMetaObject::Connection onProgress =
            connect(job, &HybridController::progressChanged, this, [&](int, const QString &stage) {
                if (!sinceCancel.isValid())
                    lastStage = stage;
            });
        QMetaObject::Connection onCancelled = connect(job, &HybridController::cancelled, this, [&] {
            stoppedAfter = sinceCancel.isValid() ? sinceCancel.elapsed() : -1;
        });
        QSignalSpy finished(hybrid, &HybridWorkflow::finished);
        const int messagesBefore = m_window->messagePanel()->count();
        HybridParams big;
        big.sites = 5000;
        QVERIFY(hybrid->start(big));
        // A timer of this scope: when the run ends first, it must not fire into a later test with
        // references to these locals (it did, and crashed progressOfALongRun).
        QTimer cancelLater;
        cancelLater.setSingleShot(true);
        connect(&cancelLater, &QTimer::timeout, this, [&] {
            if (!job->isBusy())
                return;
            sinceCancel.start();
            hybrid->cancelAction()->trigger();
        });
        cancelLater.start(delayMs);
        QVERIFY(finished.wait(kTimeoutMs));
        disconnect(onProgress);
        disconnect(onCancelled);
        if (!sinceCancel.isValid())
            QSKIP("the run ended before the cancel");
        QVERIFY(!finished.first().first().toBool());
        qInfo("cancelled %d ms into the run during '%s': the worker returned %lld ms after Cancel",
              delayMs, qPrintable(lastStage), stoppedAfter);
        QVERIFY(stoppedAfter >= 0);
        QVERIFY2(stoppedAfter < 5000, qPrintable(QString::number(stoppedAfter)));

        QVERIFY(hybrid->outcome());
        QCOMPARE(hybrid->outcome()->result, previous);
        QCOMPARE(hybrid->scenes()->output().tetCount(), int(previous->mesh.cells.size()));
        QCOMPARE(hybrid->panel()->cellText(HybridPanel::CellsRow, CellType::Tet), cells);
        QVERIFY(!job->isBusy());
        QVERIFY(hybrid->hybridAction()->isEnabled());
        QVERIFY(!hybrid->cancelAction()->isEnabled());
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);
        // The cancel is in the session's log, saying the previous mesh stays.
        const int last = m_window->messagePanel()->count() - 1;
        QVERIFY(last >= messagesBefore);
        QVERIFY(m_window->messagePanel()
                    ->cellText(last, MessagePanel::TextColumn)
                    .contains(QLatin1String("previous mesh is kept")));
    }

    void saveReadsBack()
    {
        HybridWorkflow *hybrid = m_window->hybridWorkflow();
        QVERIFY(hybrid->outcome());
        const VolumeMesh &mesh = hybrid->outcome()->result->mesh;
        QTemporaryDir dir;
        for (const QString &name : {QStringLiteral("hybrid.vtu"), QStringLiteral("hybrid.msh")}) {
            const QString path = dir.filePath(name);
            QVERIFY(hybrid->save(path));
            const VolumeMesh back = readVolumeMesh(path.toStdString());
            for (CellType type : kTypes)
                QCOMPARE(back.countCells(type), mesh.countCells(type));
            for (const Cell &c : back.cells)
                QVERIFY(signedVolume(back, c) > 0.0);
        }
        const int errors = m_window->messagePanel()->count(Message::Severity::Error);
        const QString stl = dir.filePath(QStringLiteral("hybrid.stl"));
        QVERIFY(!hybrid->save(stl));
        QVERIFY(!QFile::exists(stl));
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), errors + 1);
    }

    // A whole long run: the bar only moves forward, and the longest wait between two progress
    // updates bounds how long a Cancel can wait (stages that do not tick show up here).
    void progressOfALongRun()
    {
        HybridWorkflow *hybrid = m_window->hybridWorkflow();
        HybridController *job = hybrid->controller();
        std::vector<int> percents;
        QStringList stages;
        QElapsedTimer clock;
        qint64 last = 0, longest = 0;
        QString longestAfter;
        clock.start();
        QMetaObject::Connection onProgress = connect(
            job, &HybridController::progressChanged, this, [&](int percent, const QString &stage) {
                const qint64 now = clock.elapsed();
                if (now - last > longest) {
                    longest = now - last;
                    longestAfter = stages.isEmpty() ? QString() : stages.last();
                }
                last = now;
                percents.push_back(percent);
                stages << stage;
            });
        QSignalSpy finished(hybrid, &HybridWorkflow::finished);
        HybridParams big;
        big.sites = 5000;
        QVERIFY(hybrid->start(big));
        QVERIFY(finished.wait(kTimeoutMs));
        disconnect(onProgress);
        QVERIFY(finished.first().first().toBool());
        const HybridTimings &t = hybrid->outcome()->result->timings;
        const VolumeMesh &mesh = hybrid->outcome()->result->mesh;
        qInfo("modelA1 at 5000 sites: %zu tets, %zu pyramids, %zu prisms in %.2f s (CVT %.2f, "
              "remesh %.2f, cells %.2f, fill %.2f, check %.2f); %zu progress updates, the longest "
              "wait %lld ms after '%s'",
              mesh.countCells(CellType::Tet), mesh.countCells(CellType::Pyramid),
              mesh.countCells(CellType::Prism), t.totalSeconds, t.cvtSeconds, t.remeshSeconds,
              t.cellsSeconds, t.fillSeconds, t.checkSeconds, percents.size(), longest,
              qPrintable(longestAfter));
        for (std::size_t i = 1; i < percents.size(); ++i)
            QVERIFY2(percents[i] >= percents[i - 1], qPrintable(stages[int(i)]));
        // Where the bar stands once the CVT is over: the share the rest of the run has left.
        for (int i = 0; i < stages.size(); ++i)
            if (!stages[i].contains(QLatin1String("CVT")) && i > 0
                && stages[i - 1].contains(QLatin1String("CVT"))) {
                qInfo("after the CVT the bar is at %d %% ('%s')", percents[std::size_t(i)],
                      qPrintable(stages[i]));
                break;
            }
        QCOMPARE(hybrid->scenes()->output().tetCount(), int(mesh.cells.size()));
    }

private:
    std::unique_ptr<MainWindow> m_window;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiHybrid test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_hybrid.moc"
