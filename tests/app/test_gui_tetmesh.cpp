// Mesh > Tetrahedralise… end to end through the real controller and the TetGen helper process:
// the sample model and its remesh are tetrahedralised side by side, the Tetrahedra dock shows
// the core's figures and histograms of both, the tets are drawn in both views and a clip plane
// opens them; a helper killed mid-run is a result in the table, not an error; a cancel leaves
// nothing, and a cancel while TetGen runs kills its helper; an input-only run fills the input
// column alone.
#include "widgets/image_compare.h"

#include "comparison_table.h"
#include "histogram_chart.h"
#include "main_window.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "remesh_controller.h"
#include "remesh_workflow.h"
#include "tet_mesh_pair.h"
#include "tetmesh_controller.h"
#include "tetmesh_dialog.h"
#include "tetmesh_panel.h"
#include "tetmesh_workflow.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTabWidget>
#include <QtTest>

#include <atomic>
#include <csignal>
#include <sys/types.h>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;

bool waitForTetmesh(MainWindow &window, const TetgenParams &params, bool withRemesh,
                    bool cancelAtOnce = false)
{
    QSignalSpy finished(window.tetmeshWorkflow(), &TetmeshWorkflow::finished);
    if (!window.tetmeshWorkflow()->start(params, withRemesh))
        return false;
    if (cancelAtOnce)
        window.tetmeshWorkflow()->cancelAction()->trigger();
    if (!finished.wait(kTimeoutMs))
        return false;
    return finished.first().first().toBool();
}

double percentSum(const HistogramChart &chart, bool input)
{
    double sum = 0.0;
    for (int bin = 0; bin < chart.binCount(); ++bin)
        sum += input ? chart.inputPercent(bin) : chart.outputPercent(bin);
    return sum;
}

} // namespace

class TestGuiTetmesh : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1500, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        // Reopening the sample below drops the last result unasked.
        m_window->workbench()->setAsk([](const QString &) { return QMessageBox::Discard; });
        QVERIFY(!m_window->tetmeshWorkflow()->tetmeshAction()->isEnabled()); // nothing to mesh yet
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY(m_window->tetmeshWorkflow()->tetmeshAction()->isEnabled());
    }

    void cleanupTestCase() { m_window.reset(); }

    void dialogDefaults()
    {
        TetmeshDialog without(false, 1000.0);
        QVERIFY(!without.bothModels()); // nothing to compare with yet
        TetmeshDialog dialog(true, 1000.0);
        QVERIFY(dialog.bothModels());
        const TetgenParams p = dialog.params();
        QCOMPARE(p.quality, 1.414);
        QCOMPARE(p.maxVolume, 0.0);
        QVERIFY(!p.refineSurfaces);
        QCOMPARE(p.timeLimitSeconds, 600.0);
        TetgenParams other;
        other.quality = 2.0;
        other.maxVolume = 5000.0;
        other.refineSurfaces = true;
        other.timeLimitSeconds = 30.0;
        dialog.setParams(other);
        const TetgenParams q = dialog.params();
        QCOMPARE(q.quality, 2.0);
        QCOMPARE(q.maxVolume, 5000.0);
        QVERIFY(q.refineSurfaces);
        QCOMPARE(q.timeLimitSeconds, 30.0);
    }

    // Before any remesh: the input alone, one column.
    void inputOnly()
    {
        TetgenParams params;
        params.timeLimitSeconds = 60.0;
        QVERIFY(waitForTetmesh(*m_window, params, true)); // no remesh yet: the input alone
        const auto &outcome = m_window->tetmeshWorkflow()->outcome();
        QVERIFY(outcome && outcome->inputSide && !outcome->outputSide);
        QCOMPARE(outcome->inputSide->result.outcome, TetgenOutcome::Ok);
        TetmeshPanel *panel = m_window->tetmeshWorkflow()->panel();
        QCOMPARE(panel->cellText(TetmeshPanel::OutcomeRow, TetmeshPanel::InputColumn),
                 QStringLiteral("ok"));
        QVERIFY(panel->cellText(TetmeshPanel::OutcomeRow, TetmeshPanel::RemeshColumn).isEmpty());
        QCOMPARE(m_window->tetmeshWorkflow()->scenes()->input().tetCount(),
                 int(outcome->inputSide->quality.tets));
        QVERIFY(!m_window->tetmeshWorkflow()->scenes()->output().mesh());
        QVERIFY(!m_window->scene()->isVisible()); // the tets are drawn in place of the surfaces
        // The input's distribution alone in the Quality tab, beside no triangle comparison.
        ComparisonTable *quality = m_window->remeshWorkflow()->comparisonTable();
        QVERIFY(quality->hasTetQuality());
        QVERIFY(qAbs(percentSum(*quality->minDihedralChart(), true) - 100.0) < 1e-6);
        QVERIFY(!quality->minDihedralChart()->outputHistogram());
    }

    void cancelLeavesNothing()
    {
        QSignalSpy cancelled(m_window->tetmeshWorkflow()->controller(),
                             &TetmeshController::cancelled);
        QVERIFY(!waitForTetmesh(*m_window, TetgenParams{}, false, true));
        QCOMPARE(cancelled.size(), 1);
        QVERIFY(!m_window->tetmeshWorkflow()->outcome());
        QVERIFY(!m_window->tetmeshWorkflow()->scenes()->hasMesh());
        QVERIFY(m_window->scene()->isVisible());
        // The previous run's histograms left the Quality tab with it.
        const ComparisonTable *quality = m_window->remeshWorkflow()->comparisonTable();
        QVERIFY(!quality->hasTetQuality());
        QVERIFY(quality->chartTabs()->indexOf(quality->minDihedralChart()) < 0);
        QVERIFY(m_window->tetmeshWorkflow()->tetmeshAction()->isEnabled());
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);
    }

    // Cancel while TetGen runs: the helper is killed and reaped, nothing is shown.
    void cancelKillsTheRunningHelper()
    {
        TetgenParams params;
        params.maxVolume = 300.0; // ~10^6 tets of the sample box: TetGen runs for seconds
        std::atomic<int> helper{0};
        MainWindow *window = m_window.get();
        params.onStarted = [&helper, window](int pid) {
            helper = pid;
            QMetaObject::invokeMethod(window->tetmeshWorkflow(), &TetmeshWorkflow::cancel,
                                      Qt::QueuedConnection);
        };
        QSignalSpy cancelled(m_window->tetmeshWorkflow()->controller(),
                             &TetmeshController::cancelled);
        QElapsedTimer timer;
        timer.start();
        QVERIFY(!waitForTetmesh(*m_window, params, false));
        QCOMPARE(cancelled.size(), 1);
        QVERIFY(helper > 0);
        QVERIFY2(timer.elapsed() < 20000, qPrintable(QString::number(timer.elapsed())));
        QVERIFY(::kill(pid_t(helper.load()), 0) != 0); // gone, not left running
        QVERIFY(!m_window->tetmeshWorkflow()->outcome());
        QVERIFY(m_window->tetmeshWorkflow()->tetmeshAction()->isEnabled());
    }

    void inputAndRemeshSideBySide()
    {
        RemeshParams remesh;
        remesh.sites = 300;
        remesh.iterations = 20;
        QSignalSpy remeshed(m_window->remeshWorkflow(), &RemeshWorkflow::finished);
        QVERIFY(m_window->remeshWorkflow()->start(remesh));
        QVERIFY(remeshed.wait(kTimeoutMs));
        QVERIFY(remeshed.first().first().toBool());

        TetgenParams params;
        params.timeLimitSeconds = 60.0;
        QVERIFY(waitForTetmesh(*m_window, params, true));
        const auto &outcome = m_window->tetmeshWorkflow()->outcome();
        QVERIFY(outcome && outcome->inputSide && outcome->outputSide);
        QCOMPARE(outcome->output, m_window->remeshWorkflow()->outcome()->output);
        const TetmeshSide &in = *outcome->inputSide, &out = *outcome->outputSide;
        QCOMPARE(in.result.outcome, TetgenOutcome::Ok);
        QCOMPARE(out.result.outcome, TetgenOutcome::Ok);

        // The table holds the core's figures of both sides.
        TetmeshPanel *panel = m_window->tetmeshWorkflow()->panel();
        for (auto [column, side] : {std::pair{TetmeshPanel::InputColumn, &in},
                                    std::pair{TetmeshPanel::RemeshColumn, &out}}) {
            QCOMPARE(panel->cellText(TetmeshPanel::OutcomeRow, column), QStringLiteral("ok"));
            const qulonglong tets = panel->cellText(TetmeshPanel::TetsRow, column).toULongLong();
            QVERIFY(tets > 0);
            QCOMPARE(tets, qulonglong(side->quality.tets));
            QCOMPARE(panel->cellText(TetmeshPanel::PointsRow, column).toULongLong(),
                     qulonglong(side->quality.points));
            QCOMPARE(panel->cellText(TetmeshPanel::SliversRow, column).toULongLong(),
                     qulonglong(side->quality.slivers));
            QVERIFY(!panel->cellText(TetmeshPanel::MinDihedralRow, column).isEmpty());
            QVERIFY(!panel->cellText(TetmeshPanel::TimeRow, column).isEmpty());
        }
        QVERIFY(panel->notesText().isEmpty());
        qInfo("input %zu tets (min dihedral %.3f°, %zu slivers), remesh %zu tets (%.3f°, %zu)",
              in.quality.tets, in.quality.minDihedralDeg, in.quality.slivers, out.quality.tets,
              out.quality.minDihedralDeg, out.quality.slivers);

        // Both histograms, both sides, bin by bin in % of the tets.
        // Both histograms, in the Quality tab beside the triangles' (thesis Table 4.2).
        ComparisonTable *quality = m_window->remeshWorkflow()->comparisonTable();
        QCOMPARE(quality->chartTabs()->count(), 4);
        QVERIFY(m_window->remeshWorkflow()->comparisonDock()->isVisible());
        HistogramChart *dihedral = quality->minDihedralChart(),
                       *ratio = quality->radiusRatioChart();
        QCOMPARE(dihedral->binCount(), int(in.quality.minDihedral.binCount()));
        QCOMPARE(ratio->binCount(), int(in.quality.inverseRadiusRatio.binCount()));
        for (int bin = 0; bin < dihedral->binCount(); ++bin)
            QVERIFY(qAbs(dihedral->outputPercent(bin)
                         - 100.0 * out.quality.minDihedral.fraction(std::size_t(bin)))
                    < 1e-9);
        for (HistogramChart *chart : {dihedral, ratio}) {
            QVERIFY(qAbs(percentSum(*chart, true) - 100.0) < 1e-6);
            QVERIFY(qAbs(percentSum(*chart, false) - 100.0) < 1e-6);
        }

        // The tets are drawn in both views, in place of the surfaces.
        TetMeshPair *scenes = m_window->tetmeshWorkflow()->scenes();
        QCOMPARE(scenes->input().tetCount(), int(in.quality.tets));
        QCOMPARE(scenes->output().tetCount(), int(out.quality.tets));
        QVERIFY(!m_window->scene()->isVisible() && !m_window->outputScene()->isVisible());
        QVERIFY(m_window->outputView()->isVisible());

        // Coloured by min dihedral angle and clipped half-way: part of the tets in each view.
        panel->setColouring(TetColouring::MinDihedral);
        panel->setClip(true, ClipAxis::Y, 0.5);
        QCOMPARE(scenes->input().colouring(), TetColouring::MinDihedral);
        QVERIFY(scenes->input().isClipped() && scenes->output().isClipped());
        for (const TetMeshScene *scene : {&scenes->input(), &scenes->output()}) {
            const int shown = scene->shownTetCount();
            QVERIFY2(shown > 0 && shown < scene->tetCount(),
                     qPrintable(QStringLiteral("%1 of %2").arg(shown).arg(scene->tetCount())));
        }
        QTest::qWait(200);
        for (VtkViewWidget *view : {m_window->view(), m_window->outputView()}) {
            const QImage image = view->grabFramebuffer();
            const int drawn = test::saturatedPixels(image);
            QVERIFY2(drawn > image.width() * image.height() / 20,
                     qPrintable(QString::number(drawn)));
        }
        QVERIFY(saveWindowScreenshot(m_window.get(), QStringLiteral("/tmp/tetmesh_gui.png")));

        // Turning the plane off shows every tet again.
        panel->setClip(false, ClipAxis::Y, 0.5);
        QVERIFY(!scenes->input().isClipped());
        QCOMPARE(scenes->input().shownTetCount(), scenes->input().tetCount());
    }

    // TetGen's helper killed mid-run: the input's column says so, the remesh is still meshed.
    void killedHelperIsAResult()
    {
        TetgenParams params;
        params.timeLimitSeconds = 60.0;
        bool killed = false;
        // Only the first helper (the input's) is killed.
        params.onStarted = [&killed](int pid) {
            if (!killed) {
                killed = true;
                ::kill(pid_t(pid), SIGKILL);
            }
        };
        const int errors = m_window->messagePanel()->count(Message::Severity::Error);
        QVERIFY(waitForTetmesh(*m_window, params, true));
        const auto &outcome = m_window->tetmeshWorkflow()->outcome();
        QVERIFY(outcome && outcome->inputSide && outcome->outputSide);
        QCOMPARE(outcome->inputSide->result.outcome, TetgenOutcome::Killed);
        QCOMPARE(outcome->outputSide->result.outcome, TetgenOutcome::Ok);
        TetmeshPanel *panel = m_window->tetmeshWorkflow()->panel();
        QCOMPARE(panel->cellText(TetmeshPanel::OutcomeRow, TetmeshPanel::InputColumn),
                 QStringLiteral("killed"));
        QCOMPARE(panel->cellText(TetmeshPanel::TetsRow, TetmeshPanel::InputColumn),
                 QStringLiteral("—"));
        QVERIFY2(panel->notesText().startsWith(QStringLiteral("TetGen failed on the input after ")),
                 qPrintable(panel->notesText()));
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), errors);
        // The input's surfaces stay on screen; the remesh's tets are drawn.
        QVERIFY(m_window->scene()->isVisible());
        QVERIFY(!m_window->tetmeshWorkflow()->scenes()->input().mesh());
        QVERIFY(m_window->tetmeshWorkflow()->scenes()->output().tetCount() > 0);
    }

    void openingAnotherModelClearsTheTets()
    {
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(!m_window->tetmeshWorkflow()->outcome());
        QVERIFY(!m_window->tetmeshWorkflow()->scenes()->hasMesh());
        QVERIFY(!m_window->tetmeshWorkflow()->panel()->hasResult());
        QVERIFY(m_window->scene()->isVisible());
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
    TestGuiTetmesh test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_tetmesh.moc"
