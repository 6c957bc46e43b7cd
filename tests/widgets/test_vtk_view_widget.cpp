// The Qt6 VTK view renders a model scene inside its own OpenGL context and turns mouse
// gestures into camera moves.
#include "widgets/image_compare.h"
#include "widgets/scene_test_model.h"

#include "model_scene.h"
#include "vtk_view_widget.h"

#include <QApplication>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using namespace stratamesh;

class TestVtkViewWidget : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_view.resize(480, 360);
        m_view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_view));
        m_background = m_view.grabFramebuffer();
        QCOMPARE(m_background.size(), QSize(480, 360) * m_view.devicePixelRatio());
        m_scene = std::make_unique<ModelScene>(m_view.renderer());
        m_scene->setModel(std::make_shared<const Model>(test::sceneTestModel()));
        m_view.resetCamera();
    }

    void cleanupTestCase() { m_scene.reset(); }

    void contextIsCoreProfile32()
    {
        QVERIFY(m_view.context());
        const QSurfaceFormat f = m_view.context()->format();
        QVERIFY2(
            f.version() >= qMakePair(3, 2),
            qPrintable(QStringLiteral("OpenGL %1.%2").arg(f.majorVersion()).arg(f.minorVersion())));
        QCOMPARE(f.profile(), QSurfaceFormat::CoreProfile);
    }

    void hasMinimumSize()
    {
        QVERIFY(m_view.minimumSizeHint().width() >= 200);
        QVERIFY(m_view.minimumSizeHint().height() >= 150);
    }

    void rendersTheModel()
    {
        const QImage image = m_view.grabFramebuffer();
        const int changed = test::differingPixels(image, m_background);
        const double fraction = double(changed) / (image.width() * image.height());
        qInfo("model covers %.1f %% of the view", 100 * fraction);
        // The default camera frames the model: it must fill a good part of the view.
        QVERIFY2(fraction > 0.15, qPrintable(QString::number(fraction)));
        QVERIFY(test::saturatedPixels(image) > image.width() * image.height() / 20);
    }

    void translucentBoxKeepsTheViewOpaque()
    {
        // Alpha < 1 left by translucent actors would make Qt blend the view with what is below.
        m_scene->setBoxVisible(true);
        const QImage image = m_view.grabFramebuffer();
        m_scene->setBoxVisible(false);
        QVERIFY(image.hasAlphaChannel());
        int translucent = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                translucent += qAlpha(image.pixel(x, y)) < 255 ? 1 : 0;
        QCOMPARE(translucent, 0);
    }

    void leftDragOrbits()
    {
        vtkCamera *camera = m_view.renderer()->GetActiveCamera();
        double before[3], after[3];
        camera->GetPosition(before);
        const QPoint c = m_view.rect().center();
        QTest::mousePress(&m_view, Qt::LeftButton, Qt::NoModifier, c);
        for (int i = 1; i <= 5; ++i) {
            QMouseEvent move(QEvent::MouseMove, QPointF(c + QPoint(12 * i, 0)),
                             m_view.mapToGlobal(QPointF(c + QPoint(12 * i, 0))), Qt::NoButton,
                             Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(&m_view, &move);
        }
        QTest::mouseRelease(&m_view, Qt::LeftButton, Qt::NoModifier, c + QPoint(60, 0));
        camera->GetPosition(after);
        const double moved =
            std::hypot(after[0] - before[0], after[1] - before[1], after[2] - before[2]);
        QVERIFY2(moved > 1e-3, qPrintable(QString::number(moved)));
        // An orbit keeps the distance to the focal point.
        QVERIFY(std::abs(camera->GetDistance()
                         - std::hypot(before[0] - camera->GetFocalPoint()[0],
                                      before[1] - camera->GetFocalPoint()[1],
                                      before[2] - camera->GetFocalPoint()[2]))
                < 1e-6 * camera->GetDistance());
    }

    void wheelZooms()
    {
        vtkCamera *camera = m_view.renderer()->GetActiveCamera();
        const double before = camera->GetDistance();
        const QPointF c = m_view.rect().center();
        QWheelEvent wheel(c, m_view.mapToGlobal(c), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&m_view, &wheel);
        QVERIFY2(camera->GetDistance() < before, "wheel forward must move the camera closer");
    }

    void resetCameraLooksFromAboveWithZUp()
    {
        m_view.resetCamera();
        vtkCamera *camera = m_view.renderer()->GetActiveCamera();
        double up[3], dir[3];
        camera->GetViewUp(up);
        camera->GetDirectionOfProjection(dir);
        QVERIFY(up[2] > 0.8);   // z stays up on screen
        QVERIFY(dir[2] < -0.3); // looking down onto the model
    }

    void exitKeyIsIgnored()
    {
        // VTK binds 'q' to "exit the application"; an embedded view must swallow it.
        QTest::keyClick(&m_view, Qt::Key_Q);
        QVERIFY(m_view.isVisible());
        QVERIFY(!m_view.grabFramebuffer().isNull());
    }

private:
    VtkViewWidget m_view;
    std::unique_ptr<ModelScene> m_scene;
    QImage m_background;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    TestVtkViewWidget test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_vtk_view_widget.moc"
