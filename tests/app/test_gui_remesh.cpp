// The remesh workflow of the main window, end to end through the real controller (worker thread):
// a cancelled run leaves the input alone and shows no output; a run shows the output beside the
// input, one table row per ledger record, the Table 4.2 figures of the core comparison; the kind
// filter and the record marker work; the remeshed model is saved and reads back.
#include "widgets/image_compare.h"

#include "comparison_table.h"
#include "histogram_chart.h"
#include "io/model_reader.h"
#include "ledger_kind_filter.h"
#include "ledger_panel.h"
#include "ledger_table_model.h"
#include "main_window.h"
#include "message_panel.h"
#include "model/model_counts.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "position_marker.h"
#include "progress_strip.h"
#include "remesh/topology_refinement.h"
#include "remesh_controller.h"
#include "remesh_dialog.h"
#include "remesh_workflow.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <vtkRenderer.h>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 60000;

bool waitForRemesh(MainWindow &window, const RemeshParams &params, bool cancelAtOnce = false)
{
    QSignalSpy finished(window.remeshWorkflow(), &RemeshWorkflow::finished);
    if (!window.remeshWorkflow()->start(params))
        return false;
    if (cancelAtOnce)
        window.remeshWorkflow()->cancelAction()->trigger();
    if (!finished.wait(kTimeoutMs))
        return false;
    return finished.first().first().toBool();
}

RemeshParams smallRun()
{
    RemeshParams params;
    params.sites = 300;
    params.iterations = 20;
    return params;
}

} // namespace

class TestGuiRemesh : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1200, 800);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        // Reopening the sample below drops the last result unasked.
        m_window->workbench()->setAsk([](const QString &) { return QMessageBox::Discard; });
        QVERIFY(!m_window->remeshWorkflow()->remeshAction()->isEnabled()); // nothing to remesh yet
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY(m_window->remeshWorkflow()->remeshAction()->isEnabled());
        QVERIFY(!m_window->remeshWorkflow()->saveAction()->isEnabled());
        m_input = m_window->scene()->model();
        QVERIFY(m_input);
        m_inputTriangles = m_input->triangleCount();
        m_inputVertices = m_input->vertices.size();
    }

    void cleanupTestCase() { m_window.reset(); }

    void dialogDefaults()
    {
        RemeshDialog dialog(1000.0);
        const RemeshParams p = dialog.params();
        QCOMPARE(p.sites, RemeshDialog::kDefaultSites);
        QCOMPARE(p.edgeLength, 0.0);
        QCOMPARE(p.dResolution, kAutoDResolution);
        // The box names the automatic default rather than showing −1 m.
        auto *dBox = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("d_resolution"));
        QVERIFY(dBox);
        QCOMPARE(dBox->text(), QStringLiteral("Auto"));
        QCOMPARE(p.iterations, 100);
        QVERIFY(!p.adaptive);
        QCOMPARE(p.stripWidthFactor, RemeshParams{}.stripWidthFactor);
        QVERIFY(p.stripWidthFactor > 0.0);
        RemeshParams byLength;
        byLength.sites = 0;
        byLength.edgeLength = 25.0;
        byLength.dResolution = 2.5;
        byLength.iterations = 7;
        byLength.seed = 42;
        byLength.adaptive = true;
        byLength.stripWidthFactor = 0.0;
        dialog.setParams(byLength);
        const RemeshParams q = dialog.params();
        QCOMPARE(q.sites, 0);
        QCOMPARE(q.edgeLength, 25.0);
        QCOMPARE(q.dResolution, 2.5);
        QCOMPARE(q.iterations, 7);
        QCOMPARE(q.seed, 42u);
        QVERIFY(q.adaptive);
        QCOMPARE(q.stripWidthFactor, 0.0);
    }

    // First, while no output exists: a cancel must leave nothing behind.
    void cancelLeavesTheInputAndNoOutput()
    {
        RemeshParams big;
        big.sites = 50000;
        big.iterations = 100;
        QSignalSpy cancelled(m_window->remeshWorkflow()->controller(),
                             &RemeshController::cancelled);
        QVERIFY(!waitForRemesh(*m_window, big, true));
        QCOMPARE(cancelled.size(), 1);
        QVERIFY(!m_window->remeshWorkflow()->outcome());
        QVERIFY(!m_window->outputScene()->model());
        QVERIFY(!m_window->outputView()->isVisible());
        QCOMPARE(m_window->remeshWorkflow()->ledgerPanel()->tableModel()->rowCount(), 0);
        QCOMPARE(m_window->scene()->model(), m_input);
        QCOMPARE(m_input->triangleCount(), m_inputTriangles);
        QCOMPARE(m_input->vertices.size(), m_inputVertices);
        // The window is usable again.
        QVERIFY(!m_window->remeshWorkflow()->controller()->isBusy());
        QVERIFY(m_window->remeshWorkflow()->remeshAction()->isEnabled());
        QVERIFY(!m_window->remeshWorkflow()->cancelAction()->isEnabled());
        QVERIFY(!m_window->remeshWorkflow()->saveAction()->isEnabled());
        QCOMPARE(m_window->messagePanel()->count(Message::Severity::Error), 0);
    }

    // One strip for every workflow: the running one's stage, bar and Cancel, gone once it ends.
    void progressStripFollowsTheRun()
    {
        ProgressStrip *strip = m_window->progressStrip();
        QToolButton *cancel = strip->findChild<QToolButton *>();
        QVERIFY(cancel);
        QVERIFY(!strip->progressBar()->isVisible());
        QVERIFY(!cancel->isVisible());
        RemeshParams big;
        big.sites = 50000;
        QSignalSpy progress(m_window->remeshWorkflow()->controller(),
                            &RemeshController::progressChanged);
        QSignalSpy finished(m_window->remeshWorkflow(), &RemeshWorkflow::finished);
        QVERIFY(m_window->remeshWorkflow()->start(big));
        QVERIFY(strip->progressBar()->isVisible());
        QVERIFY(cancel->isVisible());
        QCOMPARE(cancel->defaultAction(), m_window->remeshWorkflow()->cancelAction());
        while (progress.size() < 3)
            QVERIFY(progress.wait(kTimeoutMs));
        QVERIFY2(strip->text().startsWith(QLatin1String("Remeshing")), qPrintable(strip->text()));
        const QString shots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
        QDir().mkpath(shots);
        QVERIFY(saveWindowScreenshot(m_window.get(), shots + "/remesh_running.png"));
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(!finished.first().first().toBool());
        QVERIFY(!strip->progressBar()->isVisible());
        QVERIFY(!cancel->isVisible());
        QCOMPARE(strip->text(), QStringLiteral("Remeshing cancelled"));
        QVERIFY(!m_window->remeshWorkflow()->outcome());
    }

    void remeshShowsOutputLedgerAndComparison()
    {
        QVERIFY(waitForRemesh(*m_window, smallRun()));
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        QVERIFY(outcome);
        QVERIFY(outcome->output && outcome->ledger);
        // The input is the one on screen, untouched.
        QCOMPARE(outcome->input, m_input);
        QCOMPARE(m_window->scene()->model(), m_input);
        QCOMPARE(m_input->triangleCount(), m_inputTriangles);
        // The output is drawn in its own view, beside the input.
        QCOMPARE(m_window->outputScene()->model(), outcome->output);
        QVERIFY(m_window->outputView()->isVisible());
        QVERIFY(m_window->view()->isVisible());
        // One camera for both views: they always show the same place.
        QCOMPARE(m_window->outputView()->renderer()->GetActiveCamera(),
                 m_window->view()->renderer()->GetActiveCamera());
        QCOMPARE(m_window->outputScene()->surfaceActorCount(),
                 int(outcome->output->surfaces.size()));
        QVERIFY(outcome->output->triangleCount() > 0);
        QVERIFY(outcome->output->triangleCount()
                < m_inputTriangles); // 300 sites for a 4520-triangle model
        const QImage output = m_window->outputView()->grabFramebuffer();
        const int drawn = test::saturatedPixels(output);
        qInfo("%zu output triangles, %zu ledger records, %d saturated output pixels",
              outcome->output->triangleCount(), outcome->ledger->size(), drawn);
        QVERIFY2(drawn > output.width() * output.height() / 20, qPrintable(QString::number(drawn)));

        // The features not kept are named in Messages (300 sites on the sample change its
        // topology), after the line that announces the result.
        const std::vector<std::string> changed = topologyEditEntities(*outcome->ledger);
        QVERIFY(!changed.empty());
        MessagePanel *messages = m_window->messagePanel();
        bool named = false;
        for (int row = 0; row < messages->count(); ++row) {
            const QString text = messages->message(row).text;
            named = named
                    || (text.contains(QStringLiteral("topology change"))
                        && text.contains(QString::fromStdString(changed.front())));
        }
        QVERIFY(named);

        // One row per ledger record, the summary names every kind present.
        LedgerPanel *ledger = m_window->remeshWorkflow()->ledgerPanel();
        QCOMPARE(ledger->tableModel()->rowCount(), int(outcome->ledger->size()));
        QCOMPARE(ledger->visibleRowCount(), int(outcome->ledger->size()));
        for (LedgerKind kind : LedgerTableModel::allKinds())
            if (const int n = countKind(*outcome->ledger, kind); n > 0)
                QVERIFY2(ledger->summaryText().contains(
                             QStringLiteral("%1: %2").arg(LedgerTableModel::kindText(kind)).arg(n)),
                         qPrintable(ledger->summaryText()));

        // Table 4.2 figures are the core's comparison of these two models.
        ComparisonTable *table = m_window->remeshWorkflow()->comparisonTable();
        QVERIFY(table->hasComparison());
        const ModelCounts outCounts = countEntities(*outcome->output);
        QCOMPARE(table->cellText(ComparisonTable::TrianglesRow, ComparisonTable::InputColumn),
                 QString::number(m_inputTriangles));
        QCOMPARE(table->cellText(ComparisonTable::TrianglesRow, ComparisonTable::OutputColumn),
                 QString::number(outcome->output->triangleCount()));
        QCOMPARE(table->cellText(ComparisonTable::SurfacesRow, ComparisonTable::OutputColumn),
                 QString::number(outCounts.withoutBox.surfaces));
        QCOMPARE(table->cellText(ComparisonTable::LinesRow, ComparisonTable::OutputColumn),
                 QString::number(outCounts.withoutBox.lines));
        const double hausdorff =
            table->cellText(ComparisonTable::HausdorffRow, ComparisonTable::OutputColumn)
                .toDouble();
        QVERIFY2(hausdorff > 0.0 && hausdorff < 10.0, qPrintable(QString::number(hausdorff)));
        QCOMPARE(table->cellText(ComparisonTable::HausdorffRow, ComparisonTable::InputColumn),
                 QStringLiteral("—"));
        // The histograms are the comparison's, bin by bin, in % of the triangles.
        const Histogram &inQ = outcome->comparison.inputQuality,
                        &outQ = outcome->comparison.outputQuality;
        QCOMPARE(table->qualityChart()->binCount(), int(inQ.binCount()));
        QCOMPARE(table->minAngleChart()->binCount(),
                 int(outcome->comparison.outputMinAngle.binCount()));
        double inSum = 0.0, outSum = 0.0;
        for (int bin = 0; bin < table->qualityChart()->binCount(); ++bin) {
            QVERIFY(qAbs(table->qualityChart()->inputPercent(bin)
                         - 100.0 * inQ.fraction(std::size_t(bin)))
                    < 1e-9);
            QVERIFY(qAbs(table->qualityChart()->outputPercent(bin)
                         - 100.0 * outQ.fraction(std::size_t(bin)))
                    < 1e-9);
            inSum += table->qualityChart()->inputPercent(bin);
            outSum += table->qualityChart()->outputPercent(bin);
        }
        QVERIFY2(qAbs(inSum - 100.0) < 1e-6 && qAbs(outSum - 100.0) < 1e-6,
                 qPrintable(QStringLiteral("%1 %2").arg(inSum).arg(outSum)));

        QVERIFY(m_window->remeshWorkflow()->saveAction()->isEnabled());
        QVERIFY(m_window->remeshWorkflow()->remeshAction()->isEnabled());
    }

    void filterAndMarker()
    {
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        QVERIFY(outcome);
        if (outcome->ledger->empty())
            QSKIP("this run recorded no simplification");
        LedgerPanel *ledger = m_window->remeshWorkflow()->ledgerPanel();
        const LedgerKind kind = (*outcome->ledger).back().kind;
        ledger->setKindFilter(kind);
        QCOMPARE(ledger->visibleRowCount(), countKind(*outcome->ledger, kind));
        for (int row = 0; row < ledger->visibleRowCount(); ++row)
            QCOMPARE((*outcome->ledger)[std::size_t(ledger->filter()->recordIndex(row))].kind,
                     kind);

        // Selecting a row marks the record's position in the output view.
        const int last = ledger->visibleRowCount() - 1;
        const int recordIndex = ledger->filter()->recordIndex(last);
        const QImage unmarked = m_window->outputView()->grabFramebuffer();
        ledger->selectRow(last);
        QVERIFY(m_window->remeshWorkflow()->marker()->isVisible());
        QVERIFY((m_window->remeshWorkflow()->marker()->position()
                 - (*outcome->ledger)[std::size_t(recordIndex)].position)
                    .norm()
                < 1e-12);
        const QImage marked = m_window->outputView()->grabFramebuffer();
        QVERIFY(test::differingPixels(marked, unmarked, 6) > 0);
        ledger->selectRow(-1);
        QVERIFY(!m_window->remeshWorkflow()->marker()->isVisible());

        ledger->setKindFilter(std::nullopt);
        QCOMPARE(ledger->visibleRowCount(), int(outcome->ledger->size()));
    }

    void savedModelReadsBack()
    {
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        QVERIFY(outcome);
        QTemporaryDir dir;
        for (const QString &name : {QStringLiteral("remeshed.ml"), QStringLiteral("remeshed.ts"),
                                    QStringLiteral("remeshed.gm")}) {
            const QString path = dir.filePath(name);
            QVERIFY(m_window->remeshWorkflow()->save(path));
            const Model back = readModel(path.toStdString());
            QCOMPARE(back.surfaces.size(), outcome->output->surfaces.size());
            QCOMPARE(back.triangleCount(), outcome->output->triangleCount());
        }
        // An unwritable path is an error message, not a crash.
        QVERIFY(!m_window->remeshWorkflow()->save(QStringLiteral("/nonexistent/dir/out.ml")));
        QVERIFY(m_window->messagePanel()->count(Message::Severity::Error) >= 1);
    }

    void closingWhileRemeshingStopsTheWorker()
    {
        auto window = std::make_unique<MainWindow>();
        window->show();
        QSignalSpy loaded(window->openWorkflow(), &OpenWorkflow::finished);
        window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        RemeshParams big;
        big.sites = 50000;
        QVERIFY(window->remeshWorkflow()->start(big));
        QVERIFY(window->remeshWorkflow()->controller()->isBusy());
        QVERIFY(!window->remeshWorkflow()->remeshAction()->isEnabled()); // one job at a time
        window.reset(); // cancels and waits for the worker; nothing may arrive afterwards
        QTest::qWait(50);
    }

    void openingAnotherModelClearsTheOutput()
    {
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(!m_window->remeshWorkflow()->outcome());
        QVERIFY(!m_window->outputScene()->model());
        QVERIFY(!m_window->outputView()->isVisible());
        QCOMPARE(m_window->remeshWorkflow()->ledgerPanel()->tableModel()->rowCount(), 0);
        QVERIFY(!m_window->remeshWorkflow()->saveAction()->isEnabled());
    }

private:
    std::unique_ptr<MainWindow> m_window;
    std::shared_ptr<const Model> m_input;
    std::size_t m_inputTriangles = 0;
    std::size_t m_inputVertices = 0;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiRemesh test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_remesh.moc"
