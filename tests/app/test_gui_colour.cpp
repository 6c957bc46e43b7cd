// View > Colour By, Clip Plane, histogram selection and Next Worst (issue 17) on the sample model
// and its remesh: the values drawn are the core's, bad is warm, undo restores the colouring, a bar
// selects its count, Next Worst goes by increasing Q, the clip cuts both views.
#include "comparison_table.h"
#include "gui_fixture.h"
#include "histogram_chart.h"
#include "hybrid_panel.h"
#include "hybrid_workflow.h"
#include "main_window.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "progress_strip.h"
#include "remesh/surface_remesher.h"
#include "remesh_workflow.h"
#include "tet_mesh_pair.h"
#include "tet_mesh_scene.h"
#include "tetmesh_panel.h"
#include "tetmesh_workflow.h"
#include "translations.h"
#include "view_workflow.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include "quality/triangle_measures.h"

#include <QApplication>
#include <QDir>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSlider>
#include <QSurfaceFormat>
#include <QUndoStack>
#include <QtTest>

#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkScalarBarActor.h>

#include <algorithm>
#include <cmath>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

double red(vtkLookupTable *table, double value)
{
    double rgb[3];
    table->GetColor(value, rgb);
    return rgb[0];
}

} // namespace

class TestGuiColour : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(test::openSample(*m_window, kTimeoutMs));
        QVERIFY(test::remeshOpenModel(*m_window, 300, 20, kTimeoutMs));
        m_view = m_window->viewWorkflow();
        QVERIFY(m_view);
    }

    void cleanupTestCase() { m_window.reset(); }

    void colourByQualityDrawsTheCoresValues()
    {
        QVERIFY(m_view->colourAction(Colouring::Quality)->isEnabled());
        m_view->colourAction(Colouring::Quality)->trigger();
        QCOMPARE(m_view->colourChoice().colouring, Colouring::Quality);
        const Model &output = *m_window->remeshWorkflow()->outcome()->output;
        const auto q = triangleMeasures(output, TriangleMeasure::Quality);
        ModelScene *scenes[2] = {m_window->scene(), m_window->outputScene()};
        for (ModelScene *scene : scenes) {
            QVERIFY(scene->hasScalarColouring());
            QVERIFY(scene->scalarBar()->GetVisibility());
            QCOMPARE(QString::fromUtf8(scene->scalarBar()->GetTitle()), QStringLiteral("Q"));
        }
        // Same table, same range, in both views.
        QCOMPARE(scenes[0]->lookupTable(), scenes[1]->lookupTable());
        int checked = 0;
        for (int s = 0; s < int(output.surfaces.size()); ++s) {
            vtkDataArray *scalars = scenes[1]->surfaceScalars(s);
            QVERIFY(scalars);
            QCOMPARE(scalars->GetNumberOfTuples(), vtkIdType(q[std::size_t(s)].size()));
            for (std::size_t t = 0; t < q[std::size_t(s)].size(); t += 37, ++checked)
                QCOMPARE(scalars->GetTuple1(vtkIdType(t)), q[std::size_t(s)][t]);
        }
        QVERIFY(checked > 20);
        // Low Q is bad: the warm end.
        vtkLookupTable *table = scenes[1]->lookupTable();
        QVERIFY(red(table, 0.0) > red(table, 1.0) + 0.5);
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_quality.png"));
    }

    // The View menu offers Colour By (the measures checkable, one checked) and Clip Plane.
    void viewMenuOffersTheColourings()
    {
        QMenu *view = nullptr;
        for (QAction *action : m_window->menuBar()->actions())
            if (action->text() == QStringLiteral("&View"))
                view = action->menu();
        QVERIFY(view);
        QMenu *colourBy = nullptr;
        for (QAction *action : view->actions())
            if (action->menu() && action->text() == QStringLiteral("&Colour By"))
                colourBy = action->menu();
        QVERIFY(colourBy);
        QCOMPARE(colourBy->actions().size(), 6); // four colourings, a separator, Reverse
        view->popup(m_window->mapToGlobal(QPoint(40, 30)));
        QTest::qWait(100);
        colourBy->popup(view->geometry().topRight());
        QTest::qWait(100);
        QVERIFY(view->grab().save(kShots + "/colour_view_menu.png"));
        QVERIFY(colourBy->grab().save(kShots + "/colour_colour_by_menu.png"));
        colourBy->hide();
        view->hide();
    }

    void reverseAndDistanceKeepBadWarmOrSwapIt()
    {
        m_view->reverseAction()->trigger();
        vtkLookupTable *table = m_window->outputScene()->lookupTable();
        QVERIFY(red(table, 0.0) < red(table, 1.0));
        m_window->workbench()->undoStack()->undo();
        QVERIFY(!m_view->colourChoice().reverse);

        m_view->colourAction(Colouring::Distance)->trigger();
        QCOMPARE(QString::fromUtf8(m_window->outputScene()->scalarBar()->GetTitle()),
                 QStringLiteral("Distance\n(model units)"));
        table = m_window->outputScene()->lookupTable();
        double range[2];
        table->GetTableRange(range);
        QVERIFY(range[1] > 0.0);
        QVERIFY(red(table, range[1]) > red(table, range[0]) + 0.5); // far is bad: warm
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_distance.png"));
        m_window->workbench()->undoStack()->undo();
        QCOMPARE(m_view->colourChoice().colouring, Colouring::Quality);
    }

    void undoRestoresEntityRedoQuality()
    {
        QUndoStack *undo = m_window->workbench()->undoStack();
        QVERIFY(undo->canUndo());
        undo->undo();
        QCOMPARE(m_view->colourChoice().colouring, Colouring::Entity);
        QVERIFY(m_view->colourAction(Colouring::Entity)->isChecked());
        QVERIFY(!m_window->scene()->hasScalarColouring());
        QVERIFY(!m_window->outputScene()->hasScalarColouring());
        QVERIFY(!m_window->outputScene()->scalarBar()->GetVisibility());
        undo->redo();
        QCOMPARE(m_view->colourChoice().colouring, Colouring::Quality);
        QVERIFY(m_window->outputScene()->hasScalarColouring());
        QVERIFY(m_view->colourAction(Colouring::Quality)->isChecked());
    }

    void histogramBarSelectsItsCount()
    {
        HistogramChart *chart = m_window->remeshWorkflow()->comparisonTable()->qualityChart();
        const auto &h = chart->outputHistogram();
        QVERIFY(h);
        int tested = 0;
        for (int bin = 0; bin < int(h->binCount()); ++bin) {
            if (h->counts()[std::size_t(bin)] == 0)
                continue;
            emit chart->barClicked(bin, true);
            QCOMPARE(std::size_t(m_view->selectionCount()), h->counts()[std::size_t(bin)]);
            QCOMPARE(m_window->outputScene()->highlightCount(), m_view->selectionCount());
            ++tested;
        }
        QVERIFY(tested >= 3);
        // Box triangles are counted in the bars; they are drawn only with the box.
        m_window->showBoxAction()->trigger();
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_selection_box.png"));
        m_window->showBoxAction()->trigger();
        // An input bar highlights in the input view only.
        const auto &in = chart->inputHistogram();
        const int bin =
            int(std::max_element(in->counts().begin(), in->counts().end()) - in->counts().begin());
        emit chart->barClicked(bin, false);
        QCOMPARE(std::size_t(m_window->scene()->highlightCount()), in->counts()[std::size_t(bin)]);
        QCOMPARE(m_window->outputScene()->highlightCount(), 0);
        // Min angle bars too.
        HistogramChart *angles = m_window->remeshWorkflow()->comparisonTable()->minAngleChart();
        const auto &a = angles->outputHistogram();
        const int abin =
            int(std::max_element(a->counts().begin(), a->counts().end()) - a->counts().begin());
        emit angles->barClicked(abin, true);
        QCOMPARE(std::size_t(m_view->selectionCount()), a->counts()[std::size_t(abin)]);
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_selection.png"));
        m_view->clearHighlightAction()->trigger();
        QCOMPARE(m_window->outputScene()->highlightCount(), 0);
        QCOMPARE(m_window->scene()->highlightCount(), 0);
    }

    // Two actions on one shortcut make Qt fire neither (the clip once took Ctrl+K).
    void shortcutsAreUnique()
    {
        QHash<QKeySequence, QString> seen;
        for (QAction *action : m_window->findChildren<QAction *>()) {
            for (const QKeySequence &key : action->shortcuts()) {
                QVERIFY2(
                    !seen.contains(key) || seen.value(key) == action->text(),
                    qPrintable(key.toString() + ": " + seen.value(key) + " and " + action->text()));
                seen.insert(key, action->text());
            }
        }
        QVERIFY(seen.contains(QKeySequence(Qt::Key_BracketRight)));
    }

    void nextWorstGoesByIncreasingQuality()
    {
        const Model &output = *m_window->remeshWorkflow()->outcome()->output;
        // The box is hidden: the worst of the other surfaces comes first.
        QVERIFY(!m_window->outputScene()->boxVisible());
        const auto q = triangleMeasures(output, TriangleMeasure::Quality);
        double globalMin = 2.0;
        for (std::size_t s = 0; s < q.size(); ++s)
            if (output.surfaces[s].type != FeatureType::Boundary)
                for (double v : q[s])
                    globalMin = std::min(globalMin, v);
        std::vector<double> visited;
        for (int i = 0; i < 3; ++i) {
            m_view->nextWorstAction()->trigger();
            const auto t = m_view->lastWorst();
            QVERIFY(t);
            visited.push_back(t->value);
            QVERIFY(output.surfaces[std::size_t(t->surface)].type != FeatureType::Boundary);
            QCOMPARE(m_window->outputScene()->highlightCount(), 1);
            QVERIFY(m_window->progressStrip()->text().contains(
                QString::fromStdString(output.surfaces[std::size_t(t->surface)].name)));
        }
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_next_worst.png"));
        QCOMPARE(visited[0], globalMin);
        QVERIFY(visited[0] <= visited[1] && visited[1] <= visited[2]);
    }

    void clipCutsBothViews()
    {
        ModelScene *scenes[2] = {m_window->scene(), m_window->outputScene()};
        const int before[2] = {scenes[0]->shownTriangleCount(), scenes[1]->shownTriangleCount()};
        QVERIFY(before[0] > 0 && before[1] > 0);
        m_window->workbench()->resetCamera();
        m_view->clipAction()->trigger();
        QVERIFY(m_view->clipEnabled());
        for (int i = 0; i < 2; ++i) {
            QVERIFY(scenes[i]->isClipped());
            const int after = scenes[i]->shownTriangleCount();
            qInfo("view %d: %d triangles shown of %d", i, after, before[i]);
            QVERIFY(after > 0);
            QVERIFY(after < before[i]);
        }
        // The tet meshes' clip follows (their controls and their scenes).
        QVERIFY(m_window->tetmeshWorkflow()->panel()->clipEnabled());
        QVERIFY(m_window->tetmeshWorkflow()->scenes()->isClipped());
        QVERIFY(m_window->hybridWorkflow()->panel()->clipEnabled());
        // The colouring goes through the clip: the cut surfaces stay coloured.
        QVERIFY(scenes[1]->hasScalarColouring());
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_clip.png"));
        // Undo removes the plane, redo puts it back.
        QUndoStack *undo = m_window->workbench()->undoStack();
        undo->undo();
        QVERIFY(!m_view->clipEnabled());
        QVERIFY(!m_view->clipAction()->isChecked());
        for (int i = 0; i < 2; ++i)
            QCOMPARE(scenes[i]->shownTriangleCount(), before[i]);
        undo->redo();
        QVERIFY(m_view->clipEnabled());
        // Moves of the slider are one command.
        const int count = undo->count();
        auto *slider = m_window->findChild<QSlider *>(QStringLiteral("ClipPosition"));
        QVERIFY(slider);
        slider->setValue(30);
        slider->setValue(20);
        QCOMPARE(undo->count(), count + 1);
        undo->undo();
        QCOMPARE(slider->value(), 50);
        m_view->clipAction()->trigger();
        for (int i = 0; i < 2; ++i)
            QCOMPARE(scenes[i]->shownTriangleCount(), before[i]);
        QVERIFY(!m_window->tetmeshWorkflow()->scenes()->isClipped());
        // The tet panel's own control moves the plane of the surfaces too.
        m_window->tetmeshWorkflow()->panel()->setClip(true, ClipAxis::Z, 0.5);
        QVERIFY(m_view->clipEnabled());
        QVERIFY(m_view->clipAction()->isChecked());
        for (int i = 0; i < 2; ++i)
            QVERIFY(scenes[i]->shownTriangleCount() < before[i]);
        QVERIFY(m_window->hybridWorkflow()->panel()->clipEnabled());
        m_view->clipAction()->trigger();
        QVERIFY(!m_window->tetmeshWorkflow()->panel()->clipEnabled());
    }

    // Last, as the tets replace the surfaces in the views: the same plane cuts both tet meshes.
    void clipCutsTheTetMeshesOfBothViews()
    {
        TetgenParams params;
        params.timeLimitSeconds = 60.0;
        QSignalSpy finished(m_window->tetmeshWorkflow(), &TetmeshWorkflow::finished);
        QVERIFY(m_window->tetmeshWorkflow()->start(params, true));
        QVERIFY(finished.wait(kTimeoutMs) && finished.first().first().toBool());
        TetMeshPair *tets = m_window->tetmeshWorkflow()->scenes();
        // Colouring by a quality measure colours the tets by their min dihedral angle.
        m_view->colourAction(Colouring::Entity)->trigger();
        QCOMPARE(tets->input().colouring(), TetColouring::Region);
        m_view->colourAction(Colouring::MinAngle)->trigger();
        QCOMPARE(tets->input().colouring(), TetColouring::MinDihedral);
        QCOMPARE(tets->output().colouring(), TetColouring::MinDihedral);
        QVERIFY(tets->input().mesh() && tets->output().mesh());
        QVERIFY(!tets->isClipped());
        m_view->setClip(true, ClipAxis::Y, 0.5);
        TetMeshScene *sides[2] = {&tets->input(), &tets->output()};
        for (TetMeshScene *side : sides) {
            qInfo("%d of %d tets shown", side->shownTetCount(), side->tetCount());
            QVERIFY(side->shownTetCount() > 0);
            QVERIFY(side->shownTetCount() < side->tetCount());
        }
        QVERIFY(m_window->tetmeshWorkflow()->panel()->clipEnabled());
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/colour_clip_tets.png"));
        m_view->setClip(false, ClipAxis::Y, 0.5);
        for (TetMeshScene *side : sides)
            QCOMPARE(side->shownTetCount(), side->tetCount());
    }

private:
    std::unique_ptr<MainWindow> m_window;
    ViewWorkflow *m_view = nullptr;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiColour test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_colour.moc"
