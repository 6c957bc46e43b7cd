// View > Vertical Exaggeration (issue 17): z stretched in both views, the camera framing and the
// triangle pick still right in model coordinates, undoable, kept by a project, true scale again
// for another model. View > Link Cameras: one camera for both views, or one each.
#include "exaggeration_workflow.h"
#include "gui_fixture.h"
#include "main_window.h"
#include "model_scene.h"
#include "open_workflow.h"
#include "progress_strip.h"
#include "project_workflow.h"
#include "remesh/surface_remesher.h"
#include "remesh_workflow.h"
#include "triangle_pick.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <Eigen/Geometry>

using namespace stratamesh;

namespace {
constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);

// What the view draws, in world coordinates (exaggerated).
void drawnBounds(VtkViewWidget *view, double bounds[6])
{
    view->renderer()->ComputeVisiblePropBounds(bounds);
}

double pointTriangleDistance(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    // Distance to the plane, enough here: the pick also lies within the triangle's box.
    const Vec3 n = (b - a).cross(c - a).normalized();
    return std::abs(n.dot(p - a));
}
} // namespace

class TestGuiExaggeration : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        QVERIFY(m_dir.isValid());
        m_window = std::make_unique<MainWindow>();
        m_window->workbench()->setAsk([](const QString &) { return QMessageBox::Discard; });
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QVERIFY(test::openSample(*m_window, kTimeoutMs));
        QVERIFY(test::remeshOpenModel(*m_window, 300, 15, kTimeoutMs));
        QTest::qWait(200);
    }

    void stretchesBothViews()
    {
        ExaggerationWorkflow *workflow = m_window->exaggerationWorkflow();
        QCOMPARE(workflow->exaggeration(), 1.0);
        QVERIFY(workflow->presetAction(0)->isChecked());
        double model[6], output[6], drawn[6];
        QVERIFY(m_window->scene()->bounds(model));
        QVERIFY(m_window->outputScene()->bounds(output));
        QVERIFY(model[5] - model[4] > 0.0);
        const double tolerance = 1e-6 * m_window->workbench()->diagonal();

        workflow->presetAction(2)->trigger(); // 5×
        QCOMPARE(workflow->exaggeration(), 5.0);
        QCOMPARE(m_window->view()->verticalExaggeration(), 5.0);
        QCOMPARE(m_window->outputView()->verticalExaggeration(), 5.0);
        drawnBounds(m_window->view(), drawn);
        QVERIFY(std::abs(drawn[0] - model[0]) < tolerance);
        QVERIFY(std::abs(drawn[3] - model[3]) < tolerance);
        QVERIFY2(std::abs(drawn[4] - 5.0 * model[4]) < 5.0 * tolerance,
                 qPrintable(QString("%1 vs %2").arg(drawn[4]).arg(5.0 * model[4])));
        QVERIFY(std::abs(drawn[5] - 5.0 * model[5]) < 5.0 * tolerance);
        drawnBounds(m_window->outputView(), drawn);
        QVERIFY(std::abs(drawn[4] - 5.0 * output[4]) < 5.0 * tolerance);
        QVERIFY(std::abs(drawn[5] - 5.0 * output[5]) < 5.0 * tolerance);
        QVERIFY2(m_window->progressStrip()->text().contains(QStringLiteral("5×")),
                 qPrintable(m_window->progressStrip()->text()));
    }

    // Reset View frames what is drawn: every corner of the stretched box is inside the view.
    void resetFramesTheStretchedModel()
    {
        m_window->resetCamera();
        QTest::qWait(100);
        double model[6];
        QVERIFY(m_window->scene()->bounds(model));
        vtkRenderer *renderer = m_window->view()->renderer();
        double extent = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            renderer->SetWorldPoint(model[corner & 1], model[2 + ((corner >> 1) & 1)],
                                    5.0 * model[4 + ((corner >> 2) & 1)], 1.0);
            renderer->WorldToView();
            const double *v = renderer->GetViewPoint();
            extent = std::max({extent, std::abs(v[0]), std::abs(v[1])});
        }
        QVERIFY2(extent > 0.6 && extent < 1.0, qPrintable(QString::number(extent)));
        QVERIFY(saveWindowScreenshot(m_window.get(),
                                     QDir(kShots).filePath(QStringLiteral("exaggeration.png"))));
    }

    // A click still names the triangle under the cursor, and where on it, in model coordinates.
    void pickAnswersInModelCoordinates()
    {
        const ModelScene &scene = *m_window->scene();
        m_window->view()->grabFramebuffer(); // the camera's clipping range is set by a render
        vtkRenderer *renderer = m_window->view()->renderer();
        int picked = 0;
        for (int s = 0; s < int(scene.model()->surfaces.size()); ++s) {
            if (!scene.surfaceActor(s)->GetVisibility())
                continue; // the box, hidden: not pickable
            const Surface &surface = scene.model()->surfaces[std::size_t(s)];
            const Triangle &t = surface.triangles[surface.triangles.size() / 2];
            const Vec3 c =
                (surface.vertices[std::size_t(t[0])] + surface.vertices[std::size_t(t[1])]
                 + surface.vertices[std::size_t(t[2])])
                / 3.0;
            renderer->SetWorldPoint(c.x(), c.y(), 5.0 * c.z(), 1.0);
            renderer->WorldToDisplay();
            double d[3];
            renderer->GetDisplayPoint(d);
            const auto pick = pickTriangle(scene, renderer, d[0], d[1]);
            QVERIFY2(pick, qPrintable(QString("%1 %2 in %3 x %4")
                                          .arg(d[0])
                                          .arg(d[1])
                                          .arg(renderer->GetSize()[0])
                                          .arg(renderer->GetSize()[1])));
            const Surface &hit = scene.model()->surfaces[std::size_t(pick->surface)];
            const Triangle &h = hit.triangles[std::size_t(pick->triangle)];
            const Vec3 &a = hit.vertices[std::size_t(h[0])], &b = hit.vertices[std::size_t(h[1])],
                       &cc = hit.vertices[std::size_t(h[2])];
            const double distance = pointTriangleDistance(pick->position, a, b, cc);
            QVERIFY2(distance < 1e-3 * m_window->workbench()->diagonal(),
                     qPrintable(QString("surface %1: %2").arg(pick->surface).arg(distance)));
            const Vec3 lo = a.cwiseMin(b).cwiseMin(cc), hi = a.cwiseMax(b).cwiseMax(cc);
            const double slack = 1e-3 * m_window->workbench()->diagonal();
            QVERIFY(pick->position.z() > lo.z() - slack && pick->position.z() < hi.z() + slack);
            ++picked;
        }
        QVERIFY(picked > 0);
    }

    void undoRestoresTheScale()
    {
        ExaggerationWorkflow *workflow = m_window->exaggerationWorkflow();
        QUndoStack *undo = m_window->workbench()->undoStack();
        double model[6], drawn[6];
        QVERIFY(m_window->scene()->bounds(model));
        undo->undo();
        QCOMPARE(workflow->exaggeration(), 1.0);
        drawnBounds(m_window->view(), drawn);
        QVERIFY(std::abs(drawn[4] - model[4]) < 1e-6 * m_window->workbench()->diagonal());
        QVERIFY(workflow->presetAction(0)->isChecked());
        undo->redo();
        QCOMPARE(workflow->exaggeration(), 5.0);
        QVERIFY(workflow->presetAction(2)->isChecked());
        // Out of range is clamped, and shown as the other factor it is.
        workflow->chooseExaggeration(500.0);
        QCOMPARE(workflow->exaggeration(), ExaggerationWorkflow::kMaximum);
        QVERIFY(workflow->customAction()->isChecked());
        QVERIFY(workflow->customAction()->text().contains(QStringLiteral("50×")));
        undo->undo();
        QCOMPARE(workflow->exaggeration(), 5.0);
    }

    void projectKeepsIt()
    {
        ExaggerationWorkflow *workflow = m_window->exaggerationWorkflow();
        const QString path = m_dir.filePath(QStringLiteral("stretched.smproj"));
        QVERIFY(m_window->projectWorkflow()->saveProject(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
        QCOMPARE(json.value("view").toObject().value("vertical_exaggeration").toDouble(), 5.0);

        workflow->chooseExaggeration(2.0);
        QSignalSpy done(m_window->projectWorkflow(), &ProjectWorkflow::projectOpened);
        QVERIFY(m_window->projectWorkflow()->openProject(path));
        QVERIFY(done.wait(kTimeoutMs) && done.first().first().toBool());
        QCOMPARE(workflow->exaggeration(), 5.0);
        QCOMPARE(m_window->outputView()->verticalExaggeration(), 5.0);
        emit workflow->menu()->aboutToShow();
        QVERIFY(workflow->presetAction(2)->isChecked());
    }

    void camerasLinkOrNot()
    {
        QAction *link = m_window->linkCamerasAction();
        vtkRenderer *input = m_window->view()->renderer();
        vtkRenderer *output = m_window->outputView()->renderer();
        QVERIFY(link->isChecked());
        QCOMPARE(output->GetActiveCamera(), input->GetActiveCamera());
        link->trigger();
        QVERIFY(!link->isChecked());
        QVERIFY(output->GetActiveCamera() != input->GetActiveCamera());
        double before[3], after[3];
        output->GetActiveCamera()->GetPosition(before);
        input->GetActiveCamera()->Azimuth(40.0); // the user turns the input view only
        output->GetActiveCamera()->GetPosition(after);
        QCOMPARE(after[0], before[0]);
        QCOMPARE(after[1], before[1]);
        // Both still fly to a record, each with its own camera.
        const Vec3 spot(500.0, 400.0, 200.0);
        m_window->workbench()->showPosition(spot);
        double focalIn[3], focalOut[3];
        input->GetActiveCamera()->GetFocalPoint(focalIn);
        output->GetActiveCamera()->GetFocalPoint(focalOut);
        for (int i = 0; i < 3; ++i)
            QVERIFY(std::abs(focalIn[i] - focalOut[i]) < 1e-6 * m_window->workbench()->diagonal());
        link->trigger();
        QCOMPARE(output->GetActiveCamera(), input->GetActiveCamera());
    }

    void anotherModelIsTrueScale()
    {
        QVERIFY(test::openSample(*m_window, kTimeoutMs));
        QCOMPARE(m_window->exaggerationWorkflow()->exaggeration(), 1.0);
        QCOMPARE(m_window->view()->verticalExaggeration(), 1.0);
    }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(TestGuiExaggeration)
#include "test_gui_exaggeration.moc"
