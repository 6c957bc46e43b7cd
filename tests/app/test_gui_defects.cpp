// The defects a geologist found in the window (issue 17), one test each: the window stays on the
// screen after a remesh with the Complexity dock open; a record's marker is small and the camera
// closes in on it in both views; opening another model asks before an unsaved remesh goes; a
// validity message flies the views to its place; the heat map's colour bar goes with a remesh, a
// complexity run's bar moves and a cancel is logged; the greyed edge length follows the sites;
// About lists what the menus offer; a histogram bar tells its counts; French reaches Qt's own
// buttons and the coordinates.
#include "about_dialog.h"
#include "cell_heat_map.h"
#include "comparison_table.h"
#include "complexity_controller.h"
#include "complexity_workflow.h"
#include "gui_fixture.h"
#include "histogram_chart.h"
#include "ledger_table_model.h"
#include "main_window.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "open_workflow.h"
#include "position_marker.h"
#include "progress_strip.h"
#include "remesh/surface_remesher.h"
#include "remesh_dialog.h"
#include "remesh_workflow.h"
#include "support/test_data.h"
#include "translations.h"
#include "validity_messages.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QLibraryInfo>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;

const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

Vec3 focalPoint(VtkViewWidget *view)
{
    double f[3];
    view->renderer()->GetActiveCamera()->GetFocalPoint(f);
    return {f[0], f[1], f[2]};
}

double cameraDistance(VtkViewWidget *view)
{
    return view->renderer()->GetActiveCamera()->GetDistance();
}

} // namespace

class TestGuiDefects : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->workbench()->setAsk([this](const QString &question) {
            m_questions.append(question);
            return m_answer;
        });
        QVERIFY(open());
    }

    void cleanupTestCase() { m_window.reset(); }

    // The Complexity dock stacked under Input vs Output once made the window 1110 px tall on a
    // 1000 px screen.
    void windowStaysOnTheScreenAfterRemeshWithComplexityOpen()
    {
        ComplexityParams complexity;
        complexity.cells = {100};
        QVERIFY(runComplexity(complexity));
        QVERIFY(m_window->complexityWorkflow()->heatMap()->scalarBar()->GetVisibility());
        QVERIFY(remesh());
        QTest::qWait(200);
        const int available = m_window->screen()->availableGeometry().height();
        qInfo("window %dx%d, frame height %d, minimum height %d, screen height %d",
              m_window->width(), m_window->height(), m_window->frameGeometry().height(),
              m_window->minimumSizeHint().height(), available);
        QVERIFY2(m_window->frameGeometry().height() <= available,
                 qPrintable(QString::number(m_window->frameGeometry().height())));
        QVERIFY(m_window->minimumSizeHint().height() <= available);
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/defects_remesh_complexity.png"));
    }

    // The input view halves beside the output: the colour bar of the heat map goes.
    void heatMapColourBarHiddenAfterRemesh()
    {
        QVERIFY(m_window->remeshWorkflow()->outcome());
        QVERIFY(m_window->complexityWorkflow()->outcome());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->scalarBar()->GetVisibility());
        QVERIFY(!m_window->complexityWorkflow()->heatMap()->actor()->GetVisibility());
    }

    void ledgerMarkerIsSmallAndBothViewsFly()
    {
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        QVERIFY(outcome);
        if (outcome->ledger->empty())
            QSKIP("this run recorded no simplification");
        const double diagonal = m_window->workbench()->diagonal();
        for (std::size_t i = 0; i < outcome->ledger->size(); ++i) {
            const LedgerRecord &record = (*outcome->ledger)[i];
            m_window->resetCamera();
            const double framed = cameraDistance(m_window->view());
            m_window->remeshWorkflow()->showLedgerRecord(int(i));
            PositionMarker *out = m_window->remeshWorkflow()->marker();
            PositionMarker *in = m_window->workbench()->inputMarker();
            QVERIFY(out->isVisible() && in->isVisible());
            QVERIFY2(out->radius() <= 0.05 * diagonal,
                     qPrintable(QStringLiteral("record %1: radius %2, diagonal %3")
                                    .arg(i)
                                    .arg(out->radius())
                                    .arg(diagonal)));
            QVERIFY((in->position() - record.position).norm() < 1e-9);
            QVERIFY((focalPoint(m_window->view()) - record.position).norm() < 1e-6 * diagonal);
            QVERIFY((focalPoint(m_window->outputView()) - record.position).norm()
                    < 1e-6 * diagonal);
            QVERIFY2(
                cameraDistance(m_window->view()) < 0.75 * framed,
                qPrintable(
                    QStringLiteral("%1 vs %2").arg(cameraDistance(m_window->view())).arg(framed)));
        }
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/defects_ledger_marker.png"));
        // A record whose size is an area (an unresolved intersection) is no radius.
        m_window->workbench()->showPosition((*outcome->ledger)[0].position, 10.0 * diagonal);
        QVERIFY(m_window->remeshWorkflow()->marker()->radius() <= 0.05 * diagonal);
        m_window->remeshWorkflow()->showLedgerRecord(-1);
        QVERIFY(!m_window->remeshWorkflow()->marker()->isVisible());
        QVERIFY(!m_window->workbench()->inputMarker()->isVisible());
    }

    void histogramBarTellsItsCounts()
    {
        const auto &outcome = m_window->remeshWorkflow()->outcome();
        QVERIFY(outcome);
        HistogramChart *chart = m_window->remeshWorkflow()->comparisonTable()->qualityChart();
        QVERIFY(chart->binCount() > 0);
        const int bin = 0; // the worst quality
        const std::size_t count = outcome->comparison.outputQuality.counts()[0];
        const QString tip = chart->barToolTip(bin);
        QVERIFY2(tip.contains(QStringLiteral("%1 triangle").arg(count)), qPrintable(tip));
        QVERIFY(chart->minimumHeight() >= 200);
    }

    void openAsksBeforeAnUnsavedRemeshGoes()
    {
        QVERIFY(m_window->remeshWorkflow()->outcome());
        QVERIFY(!m_window->remeshWorkflow()->unsavedWork().isEmpty());
        m_questions.clear();
        m_answer = QMessageBox::Cancel;
        m_window->openSample();
        m_window->openFile(test::dataFile(QStringLiteral("not_sealed_cube.ml")));
        QCOMPARE(m_questions.size(), 2);
        QVERIFY(!m_window->openWorkflow()->controller()->isBusy());
        QVERIFY(m_window->remeshWorkflow()->outcome()); // kept
        QVERIFY(m_window->outputScene()->model());

        // Once saved, nothing is asked.
        QTemporaryDir dir;
        QVERIFY(m_window->remeshWorkflow()->save(dir.filePath(QStringLiteral("out.ml"))));
        QVERIFY(m_window->remeshWorkflow()->unsavedWork().isEmpty());
        QVERIFY(remesh());
        m_questions.clear();
        m_answer = QMessageBox::Discard;
        QVERIFY(open());
        QCOMPARE(m_questions.size(), 1);
        QVERIFY(!m_window->remeshWorkflow()->outcome());
    }

    void cancelledComplexityIsLoggedAndTheBarMoves()
    {
        ComplexityParams big;
        big.cells = {200000};
        const int before = m_window->messagePanel()->count();
        QSignalSpy finished(m_window->complexityWorkflow(), &ComplexityWorkflow::finished);
        QVERIFY(m_window->complexityWorkflow()->start(big));
        QProgressBar *bar = m_window->progressStrip()->progressBar();
        QTRY_VERIFY_WITH_TIMEOUT(bar->value() > 0, kTimeoutMs);
        m_window->complexityWorkflow()->cancelAction()->trigger();
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(!finished.first().first().toBool());
        QCOMPARE(m_window->messagePanel()->count(), before + 1);
        QVERIFY(m_window->messagePanel()
                    ->cellText(before, MessagePanel::TextColumn)
                    .contains(QLatin1String("cancelled")));
    }

    void edgeLengthEstimateFollowsTheSites()
    {
        const auto model = m_window->scene()->model();
        RemeshDialog dialog(m_window->workbench()->diagonal());
        dialog.setModelArea(modelArea(*model));
        auto *sites = dialog.findChild<QSpinBox *>(QStringLiteral("sites"));
        auto *length = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("edge_length"));
        auto *dResolution = dialog.findChild<QDoubleSpinBox *>(QStringLiteral("d_resolution"));
        QVERIFY(sites && length && dResolution);
        QVERIFY(!length->isEnabled());
        sites->setValue(1000);
        const double at1000 = length->value();
        sites->setValue(4000);
        const double at4000 = length->value();
        QVERIFY2(qAbs(at1000 / at4000 - 2.0) < 0.05,
                 qPrintable(QStringLiteral("%1 %2").arg(at1000).arg(at4000)));
        QVERIFY(qAbs(at4000 - edgeLengthForSites(modelArea(*model), 4000)) <= 0.01 * at4000);
        QVERIFY(!length->suffix().trimmed().isEmpty());
        QVERIFY(!dResolution->suffix().trimmed().isEmpty());
        // Every flag of the table is offered, the pinned refinement off by default.
        auto *pins = dialog.findChild<QCheckBox *>(QStringLiteral("pin_features"));
        QVERIFY(pins && !pins->isChecked());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QVERIFY(dialog.grab().save(kShots + "/remesh_dialog.png"));
    }

    // About lists the Mesh and Analyse actions: nothing that no menu offers.
    void aboutNamesWhatTheMenusOffer()
    {
        const QStringList offered = m_window->offeredActions();
        QVERIFY(!offered.isEmpty());
        const QString about = aboutText(offered);
        bool hybridOffered = false;
        for (QString text : offered) {
            text.remove(QLatin1Char('&'));
            text.remove(QChar(0x2026));
            QVERIFY2(about.contains(text), qPrintable(text));
            hybridOffered |= text.contains(QLatin1String("hybrid"), Qt::CaseInsensitive);
            QVERIFY(!text.startsWith(QLatin1String("Cancel")));
        }
        QVERIFY(about.contains(QLatin1String("Tetrahedralise")));
        QCOMPARE(about.contains(QLatin1String("hybrid"), Qt::CaseInsensitive), hybridOffered);
    }

    // A validity problem's message knows its place: clicking it flies both views there.
    void validityMessageFliesTheViews()
    {
        STRATAMESH_REQUIRE_DATA(path, "not_sealed_cube.ml");
        m_answer = QMessageBox::Discard;
        QVERIFY(open(path));
        MessagePanel *messages = m_window->messagePanel();
        int row = -1;
        for (int r = 0; r < messages->count() && row < 0; ++r)
            if (messages->message(r).position)
                row = r;
        QVERIFY2(row >= 0, "no validity message with a position");
        const Vec3 where = *messages->message(row).position;
        m_window->resetCamera();
        const double framed = cameraDistance(m_window->view());
        messages->activate(row);
        const double diagonal = m_window->workbench()->diagonal();
        QVERIFY((focalPoint(m_window->view()) - where).norm() < 1e-6 * diagonal);
        QVERIFY(cameraDistance(m_window->view()) < framed);
        QVERIFY(m_window->workbench()->inputMarker()->isVisible());
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/defects_validity_click.png"));
    }

    void frenchReachesQtButtonsAndCoordinates()
    {
        QVERIFY(QFile::exists(QLibraryInfo::path(QLibraryInfo::TranslationsPath)
                              + QStringLiteral("/qtbase_fr.qm")));
        QCOMPARE(installTranslations(QStringLiteral("fr")), QStringLiteral("fr"));
        {
            RemeshDialog dialog(1000.0);
            auto *box = dialog.findChild<QDialogButtonBox *>();
            QVERIFY(box);
            QCOMPARE(box->button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Annuler"));
        }
        {
            QFileDialog dialog(m_window.get());
            dialog.setOption(QFileDialog::DontUseNativeDialog);
            auto *box = dialog.findChild<QDialogButtonBox *>();
            QVERIFY(box);
            QCOMPARE(box->button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Annuler"));
            QVERIFY2(box->button(QDialogButtonBox::Open)->text().contains(QLatin1String("Ouvrir")),
                     qPrintable(box->button(QDialogButtonBox::Open)->text()));
        }
        const QString position = LedgerTableModel::positionText(Vec3(140.0, 3302.3, -12.5));
        QVERIFY2(position.contains(QLatin1String("140,0; ")), qPrintable(position));
        QCOMPARE(position.count(QLatin1Char(';')), 2);
        installTranslations(QStringLiteral("en"));
        QLocale::setDefault(QLocale::c());
    }

private:
    bool open(const QString &path = QString())
    {
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        if (path.isEmpty())
            m_window->openSample();
        else
            m_window->openFile(path);
        return loaded.wait(kTimeoutMs) && loaded.first().first().toBool();
    }

    bool remesh() { return test::remeshOpenModel(*m_window, 300, 20, kTimeoutMs); }

    bool runComplexity(const ComplexityParams &params)
    {
        QSignalSpy finished(m_window->complexityWorkflow(), &ComplexityWorkflow::finished);
        return m_window->complexityWorkflow()->start(params) && finished.wait(kTimeoutMs)
               && finished.first().first().toBool();
    }

    std::unique_ptr<MainWindow> m_window;
    QStringList m_questions;
    QMessageBox::StandardButton m_answer = QMessageBox::Discard;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiDefects test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_defects.moc"
