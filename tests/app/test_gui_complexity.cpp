// The complexity workflow of the main window (thesis ch. 3), end to end through the real
// controller (worker thread): a cancelled run leaves the window usable with no heat map; a run
// shows the core's Tables 3.1–3.4 figures in the Complexity dock and one heat-map polyhedron per
// cell reaching the threshold (Fig 3.7); the threshold and the toggle change what is drawn; the
// cells are exported as .vtu.
#include "widgets/image_compare.h"

#include "cell_heat_map.h"
#include "complexity/complexity_report.h"
#include "complexity_controller.h"
#include "complexity_dialog.h"
#include "complexity_panel.h"
#include "complexity_workflow.h"
#include "gui_options.h"
#include "main_window.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "remesh_workflow.h"
#include "translations.h"
#include "vtk_view_widget.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QLocale>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkScalarBarActor.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <set>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 60000;

bool waitForComplexity(MainWindow &window, const ComplexityParams &params,
                       bool cancelAtOnce = false)
{
    QSignalSpy finished(window.complexityWorkflow(), &ComplexityWorkflow::finished);
    if (!window.complexityWorkflow()->start(params))
        return false;
    if (cancelAtOnce)
        window.complexityWorkflow()->cancelAction()->trigger();
    if (!finished.wait(kTimeoutMs))
        return false;
    return finished.first().first().toBool();
}

ComplexityParams smallRun()
{
    ComplexityParams params;
    params.cells = {100};
    params.seed = 7;
    return params;
}

// Cells whose total count is at least the threshold.
int cellsAtLeast(const LocalComplexity &local, int threshold)
{
    int n = 0;
    for (const CellElementCounts &c : local.counts)
        n += c.total() >= threshold ? 1 : 0;
    return n;
}

} // namespace

class TestGuiComplexity : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1200, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(!m_window->complexityWorkflow()
                     ->analyseAction()
                     ->isEnabled()); // nothing to measure yet
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY(m_window->complexityWorkflow()->analyseAction()->isEnabled());
        QVERIFY(!m_window->complexityWorkflow()->exportAction()->isEnabled());
        m_model = m_window->scene()->model();
        QVERIFY(m_model);
    }

    void cleanupTestCase() { m_window.reset(); }

    void dialogDefaults()
    {
        ComplexityDialog dialog;
        const ComplexityParams p = dialog.params();
        QCOMPARE(p.geometric.h, 100.0);
        QCOMPARE(p.geometric.alphaDegrees, 20.0);
        QCOMPARE(p.cells, std::vector<int>{ComplexityDialog::kDefaultCells});
        QCOMPARE(p.seed, std::uint64_t(1));
        ComplexityParams other;
        other.geometric.h = 25.5;
        other.geometric.alphaDegrees = 35.0;
        other.cells = {12000};
        other.seed = 42;
        dialog.setParams(other);
        const ComplexityParams q = dialog.params();
        QCOMPARE(q.geometric.h, 25.5);
        QCOMPARE(q.geometric.alphaDegrees, 35.0);
        QCOMPARE(q.cells, std::vector<int>{12000}); // more than 10000 cells allowed
        QCOMPARE(q.seed, std::uint64_t(42));
    }

    void commandLineOption()
    {
        GuiOptions options;
        int exitCode = -1;
        QVERIFY(parseGuiOptions({QStringLiteral("stratamesh"), QStringLiteral("--complexity-cells"),
                                 QStringLiteral("500"), QStringLiteral("m.ml")},
                                options, exitCode));
        QCOMPARE(int(options.steps.size()), 1);
        QCOMPARE(options.steps[0].kind, ScriptStep::Kind::Complexity);
        QCOMPARE(options.steps[0].count, 500);
        QCOMPARE(options.openPath, QStringLiteral("m.ml"));
        GuiOptions bad;
        QVERIFY(!parseGuiOptions({QStringLiteral("stratamesh"),
                                  QStringLiteral("--complexity-cells"), QStringLiteral("0")},
                                 bad, exitCode));
        QCOMPARE(exitCode, 2);
    }

    // First, while nothing was measured: a cancel must leave nothing behind.
    void cancelLeavesNoHeatMap()
    {
        ComplexityParams big;
        big.cells = {200000};
        QSignalSpy cancelled(m_window->complexityWorkflow()->controller(),
                             &ComplexityController::cancelled);
        QVERIFY(!waitForComplexity(*m_window, big, true));
        QCOMPARE(cancelled.size(), 1);
        QVERIFY(!m_window->complexityWorkflow()->outcome());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->hasCells());
        QCOMPARE(m_window->complexityWorkflow()->heatMap()->polyData()->GetNumberOfCells(),
                 vtkIdType(0));
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->actor()->GetVisibility());
        QVERIFY(!m_window->complexityWorkflow()->panel()->hasReport());
        // The window is usable again.
        QVERIFY(!m_window->complexityWorkflow()->controller()->isBusy());
        QVERIFY(m_window->complexityWorkflow()->analyseAction()->isEnabled());
        QVERIFY(m_window->remeshWorkflow()->remeshAction()->isEnabled());
        QVERIFY(!m_window->complexityWorkflow()->cancelAction()->isEnabled());
        QVERIFY(!m_window->complexityWorkflow()->exportAction()->isEnabled());
        QCOMPARE(m_window->scene()->model(), m_model);
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);
    }

    void dockShowsTheCoreFigures()
    {
        const ComplexityParams params = smallRun();
        QSignalSpy progress(m_window->complexityWorkflow()->controller(),
                            &ComplexityController::progressChanged);
        QVERIFY(waitForComplexity(*m_window, params));
        // The bar only moves forward through the stages and ends full.
        QVERIFY(!progress.isEmpty());
        for (qsizetype k = 1; k < progress.size(); ++k)
            QVERIFY(progress[k].first().toInt() >= progress[k - 1].first().toInt());
        QCOMPARE(progress.last().first().toInt(), 100);
        const auto &outcome = m_window->complexityWorkflow()->outcome();
        QVERIFY(outcome);
        QCOMPARE(outcome->model, m_model);
        // The same computation by the core, here in the test thread.
        const ComplexityReport core = computeComplexity(*m_model, params);
        QCOMPARE(core.local.size(), std::size_t(1));
        const ComplexityPanel *panel = m_window->complexityWorkflow()->panel();
        QVERIFY(panel->hasReport());
        const QLocale c = QLocale::c();
        using P = ComplexityPanel;
        const EntityCounts &n = core.counts;
        QCOMPARE(panel->globalText(P::CountsRow, P::RegionsColumn), QString::number(n.regions));
        QCOMPARE(panel->globalText(P::CountsRow, P::SurfacesColumn), QString::number(n.surfaces));
        QCOMPARE(panel->globalText(P::CountsRow, P::LinesColumn), QString::number(n.lines));
        QCOMPARE(panel->globalText(P::CountsRow, P::CornersColumn), QString::number(n.corners));
        QCOMPARE(panel->globalText(P::CountsRow, P::TotalColumn),
                 QString::number(n.regions + n.surfaces + n.lines + n.corners));
        QVERIFY(n.surfaces > 0);
        QCOMPARE(panel->globalText(P::GeometricRow, P::RegionsColumn),
                 c.toString(core.geometric.regionsTotal, 'f', 2));
        QCOMPARE(panel->globalText(P::GeometricRow, P::SurfacesColumn),
                 c.toString(core.geometric.surfacesTotal, 'f', 2));
        QCOMPARE(panel->globalText(P::GeometricRow, P::LinesColumn),
                 c.toString(core.geometric.linesTotal, 'f', 2));
        QCOMPARE(panel->globalText(P::GeometricRow, P::TotalColumn),
                 c.toString(core.geometric.total(), 'f', 2));
        QCOMPARE(panel->globalText(P::VariationRow, P::RegionsColumn),
                 c.toString(core.variation.regions, 'f', 2));
        QCOMPARE(panel->globalText(P::VariationRow, P::SurfacesColumn),
                 c.toString(core.variation.surfaces, 'f', 2));
        QCOMPARE(panel->globalText(P::VariationRow, P::LinesColumn),
                 c.toString(core.variation.lines, 'f', 2));
        QCOMPARE(panel->globalText(P::VariationRow, P::TotalColumn),
                 c.toString(core.variation.total, 'f', 2));
        const LocalComplexity &local = core.local.front();
        const CountStatistics &s = local.statistics;
        QCOMPARE(local.counts.size(), std::size_t(100));
        QCOMPARE(panel->localText(P::CellsRow), QStringLiteral("100"));
        QCOMPARE(panel->localText(P::Q10Row), QString::number(s.q10));
        QCOMPARE(panel->localText(P::Q50Row), QString::number(s.q50));
        QCOMPARE(panel->localText(P::Q90Row), QString::number(s.q90));
        QCOMPARE(panel->localText(P::MaxRow), QString::number(s.max));
        QCOMPARE(panel->localText(P::MeanRow), c.toString(s.mean, 'f', 3));
        QCOMPARE(panel->localText(P::VarCoeffRow), c.toString(s.varCoeff, 'f', 3));
        QVERIFY(s.max > s.q10); // some cells meet more elements than others: a real heat map
        QVERIFY(m_window->complexityWorkflow()->exportAction()->isEnabled());
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);
    }

    // One polyhedron per cell reaching the threshold; the faces between two drawn cells are left
    // out, every other face of a drawn cell is there, coloured by that cell's count.
    void heatMapHasTheCellsAboveTheThreshold()
    {
        const auto &outcome = m_window->complexityWorkflow()->outcome();
        QVERIFY(outcome);
        const LocalComplexity &local = outcome->local();
        CellHeatMap *heatMap = m_window->complexityWorkflow()->heatMap();
        QCOMPARE(heatMap->threshold(), ComplexityPanel::kDefaultThreshold);
        const auto check = [&](int threshold) {
            QCOMPARE(heatMap->shownCellCount(), cellsAtLeast(local, threshold));
            vtkPolyData *poly = heatMap->polyData();
            auto *ids = vtkIntArray::SafeDownCast(poly->GetCellData()->GetArray("CellId"));
            auto *counts = vtkIntArray::SafeDownCast(poly->GetCellData()->GetArray("count"));
            QVERIFY(ids && counts);
            std::vector<int> faces(local.counts.size(), 0);
            for (vtkIdType k = 0; k < poly->GetNumberOfCells(); ++k) {
                const int id = ids->GetValue(k);
                QVERIFY(id >= 0 && id < int(local.counts.size()));
                QCOMPARE(counts->GetValue(k), local.counts[id].total());
                QVERIFY(local.counts[id].total() >= threshold);
                ++faces[id];
            }
            const auto drawn = [&](int j) {
                return j >= 0 && local.counts[j].total() >= threshold;
            };
            for (std::size_t i = 0; i < local.counts.size(); ++i) {
                int expected = 0;
                if (drawn(int(i)))
                    for (int f = 0; f < local.cvt.cells[i].faceCount(); ++f)
                        expected += drawn(local.cvt.cells[i].facePlane(f).tag) ? 0 : 1;
                QCOMPARE(faces[i], expected);
            }
        };
        check(ComplexityPanel::kDefaultThreshold);
        QVERIFY(heatMap->actor()->GetVisibility());
        QVERIFY(heatMap->scalarBar()->GetVisibility());
        QCOMPARE(heatMap->maxCount(), local.statistics.max);

        // The spin box of the dock drives the filter.
        const int before = heatMap->shownCellCount();
        const int higher = local.statistics.q90;
        QVERIFY(cellsAtLeast(local, higher) != before);
        m_window->complexityWorkflow()->panel()->thresholdBox()->setValue(higher);
        QCOMPARE(heatMap->threshold(), higher);
        check(higher);
        QVERIFY(heatMap->shownCellCount() != before);
        m_window->complexityWorkflow()->panel()->thresholdBox()->setValue(0);
        check(0);
        QCOMPARE(heatMap->shownCellCount(), int(local.counts.size()));
        m_window->complexityWorkflow()->panel()->thresholdBox()->setValue(
            ComplexityPanel::kDefaultThreshold);
        check(ComplexityPanel::kDefaultThreshold);
    }

    void toggleChangesTheImage()
    {
        QVERIFY(m_window->complexityWorkflow()->outcome());
        m_window->resetCamera();
        QCheckBox *toggle = m_window->complexityWorkflow()->panel()->heatMapBox();
        QVERIFY(toggle->isChecked());
        m_window->view()->render();
        const QImage with = m_window->view()->grabFramebuffer();
        toggle->setChecked(false);
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->actor()->GetVisibility());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->scalarBar()->GetVisibility());
        m_window->view()->render();
        const QImage without = m_window->view()->grabFramebuffer();
        const int changed = test::differingPixels(with, without);
        QVERIFY2(changed > with.width() * with.height() / 50, qPrintable(QString::number(changed)));
        toggle->setChecked(true);
        m_window->view()->render();
        QCOMPARE(test::differingPixels(m_window->view()->grabFramebuffer(), with, 6), 0);
    }

    void exportedCellsReadBack()
    {
        const auto &outcome = m_window->complexityWorkflow()->outcome();
        QVERIFY(outcome);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("cells.vtu"));
        QVERIFY(m_window->complexityWorkflow()->exportCells(path));
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(path.toUtf8().constData());
        reader->Update();
        vtkUnstructuredGrid *grid = reader->GetOutput();
        QCOMPARE(grid->GetNumberOfCells(), vtkIdType(outcome->local().counts.size()));
        auto *total = grid->GetCellData()->GetArray("total");
        QVERIFY(total);
        for (vtkIdType k = 0; k < grid->GetNumberOfCells(); ++k)
            QCOMPARE(int(total->GetTuple1(k)), outcome->local().counts[std::size_t(k)].total());
        // An unwritable path is an error message, not a crash.
        QVERIFY(!m_window->complexityWorkflow()->exportCells(
            QStringLiteral("/nonexistent/dir/cells.vtu")));
        QVERIFY(m_window->messagePanel()->count(Message::Severity::Error) >= 1);
    }

    void closingWhileMeasuringStopsTheWorker()
    {
        auto window = std::make_unique<MainWindow>();
        window->show();
        QSignalSpy loaded(window->openWorkflow(), &OpenWorkflow::finished);
        window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        ComplexityParams big;
        big.cells = {200000};
        QVERIFY(window->complexityWorkflow()->start(big));
        QVERIFY(window->complexityWorkflow()->controller()->isBusy());
        QVERIFY(!window->complexityWorkflow()->analyseAction()->isEnabled()); // one job at a time
        QVERIFY(!window->remeshWorkflow()->remeshAction()->isEnabled());
        QVERIFY(!window->remeshWorkflow()->start(RemeshParams{}));
        window.reset(); // cancels and waits for the worker; nothing may arrive afterwards
        QTest::qWait(50);
    }

    void openingAnotherModelClearsTheHeatMap()
    {
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(!m_window->complexityWorkflow()->outcome());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->hasCells());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->actor()->GetVisibility());
        QVERIFY(!m_window->complexityWorkflow()->panel()->hasReport());
        QVERIFY(!m_window->complexityWorkflow()->exportAction()->isEnabled());
    }

private:
    std::unique_ptr<MainWindow> m_window;
    std::shared_ptr<const Model> m_model;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiComplexity test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_complexity.moc"
