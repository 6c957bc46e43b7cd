// A Qt6 OpenGL widget that hosts a VTK renderer. Debian's VTK Qt module is built against Qt5,
// so this drives a vtkGenericOpenGLRenderWindow inside the QOpenGLWidget's own context instead.
#pragma once

#include <QOpenGLWidget>
#include <QPointF>
#include <QSurfaceFormat>
#include <QTimer>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkCallbackCommand;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkInteractorStyleTrackballCamera;
class vtkMatrix4x4;
class vtkObject;
class vtkOrientationMarkerWidget;
class vtkRenderer;

namespace stratamesh {

class VtkViewWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit VtkViewWidget(QWidget *parent = nullptr);
    ~VtkViewWidget() override;

    // OpenGL 3.2 core profile with depth and stencil, as VTK's OpenGL2 backend needs. Set it as
    // the default format before creating the QApplication.
    static QSurfaceFormat defaultFormat();

    vtkRenderer *renderer() const;
    vtkGenericOpenGLRenderWindow *renderWindow() const;
    vtkGenericRenderWindowInteractor *interactor() const;

    // Geologist's default view: z up, looking north-east and down at ~30 degrees, all visible.
    void resetCamera();
    // The same view direction, framing the given bounds (xmin, xmax, ymin, ymax, zmin, zmax).
    void resetCamera(const double bounds[6]);
    // Keeps the view direction and distance and moves the camera so that `point` is in the
    // centre (a ledger record, a validity problem); does not render.
    void centreOn(const double point[3]);
    // The same view direction, `point` in the centre, and the camera no farther than `distance`
    // from it: close enough to see the spot, with its surroundings; does not render.
    void flyTo(const double point[3], double distance);
    // Schedules a repaint; VTK only ever renders inside paintGL.
    void render();

    // Z stretched by `factor` about z = 0 (a geologist's vertical exaggeration: thin layers and
    // low dips become visible). Every 3D prop of the renderer is drawn through it, props added
    // later too; the points and bounds given to the camera methods above stay model coordinates.
    // The camera is not moved (ViewPair moves the one its views share).
    void setVerticalExaggeration(double factor);
    double verticalExaggeration() const { return m_exaggeration; }

    static constexpr int kHoverDelayMs = 300;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

signals:
    // The user moved the camera (mouse, wheel, keys): views sharing the camera repaint on it.
    void cameraMovedByUser();
    // A left click without drag, at VTK display coordinates (device pixels, origin bottom left):
    // what lies there can be picked.
    void clicked(double x, double y);
    // The pointer rested on the view (no button down) for kHoverDelayMs, at VTK display
    // coordinates as for clicked(): what lies there can be described without selecting it.
    void hovered(double x, double y);
    // The pointer moved away, a button went down, or the pointer left the view: a description
    // shown for the last hover is out of date.
    void hoverEnded();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void enterEvent(QEnterEvent *event) override;
    void leaveEvent(QEvent *event) override;

private:
    static void onVtkEvent(vtkObject *caller, unsigned long eventId, void *clientData,
                           void *callData);
    void setPointerInfo(const QPointF &pos, Qt::KeyboardModifiers modifiers);
    // VTK display coordinates (device pixels, origin bottom left) of a Qt widget position.
    QPointF displayPosition(const QPointF &pos) const;
    void endHover();
    void cleanupGL();
    // Gives every 3D prop the exaggeration's matrix (none at 1×); at each paint and before bounds.
    void applyExaggeration();
    void frame(const double worldBounds[6]);
    void onContextAboutToBeDestroyed();

    vtkNew<vtkGenericOpenGLRenderWindow> m_renderWindow;
    vtkNew<vtkRenderer> m_renderer;
    vtkNew<vtkGenericRenderWindowInteractor> m_interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> m_style;
    vtkNew<vtkCallbackCommand> m_callback;
    vtkSmartPointer<vtkOrientationMarkerWidget> m_axes;
    vtkNew<vtkMatrix4x4> m_exaggerationMatrix;
    double m_exaggeration = 1.0;
    bool m_initialized = false;
    QPointF m_leftPress{-1.0, -1.0}; // where the left button went down, to tell a click from a drag
    // Picking on every mouse move would cost a ray cast per event; the pointer must rest first.
    QTimer m_hoverTimer;
    QPointF m_hoverPos;
    bool m_hoverShown = false;
};

} // namespace stratamesh
