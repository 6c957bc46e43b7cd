#include "vtk_view_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <vtkAxesActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLightKit.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLState.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkProp3D.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {

int vtkButtonEvent(Qt::MouseButton button, bool press)
{
    switch (button) {
    case Qt::LeftButton:
        return press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::MiddleButton:
        return press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    case Qt::RightButton:
        return press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    default:
        return vtkCommand::NoEvent;
    }
}

// X11-style key names that vtkInteractorStyle compares against.
const char *keySym(int key)
{
    switch (key) {
    case Qt::Key_Left:
        return "Left";
    case Qt::Key_Right:
        return "Right";
    case Qt::Key_Up:
        return "Up";
    case Qt::Key_Down:
        return "Down";
    case Qt::Key_Shift:
        return "Shift_L";
    case Qt::Key_Control:
        return "Control_L";
    case Qt::Key_Plus:
        return "plus";
    case Qt::Key_Minus:
        return "minus";
    default:
        return nullptr;
    }
}

// VTK's default key bindings include 'e'/'q' (exit the application) and '3' (stereo); a viewer
// embedded in a main window must not honour those.
bool isForwardedKey(const QKeyEvent *event)
{
    const QString text = event->text().toLower();
    return !(text == QLatin1String("e") || text == QLatin1String("q")
             || text == QLatin1String("3"));
}

void configureAxesLabel(vtkCaptionActor2D *caption)
{
    vtkTextProperty *p = caption->GetCaptionTextProperty();
    p->SetColor(0.15, 0.15, 0.18);
    p->ShadowOff();
    p->ItalicOff();
    p->BoldOn();
    p->SetFontSize(14);
}

} // namespace

VtkViewWidget::VtkViewWidget(QWidget *parent) : QOpenGLWidget(parent)
{
    setFormat(defaultFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);
    m_hoverTimer.setSingleShot(true);
    m_hoverTimer.setInterval(kHoverDelayMs);
    connect(&m_hoverTimer, &QTimer::timeout, this, [this] {
        const QPointF p = displayPosition(m_hoverPos);
        m_hoverShown = true;
        emit hovered(p.x(), p.y());
    });

    // The context belongs to Qt: VTK must neither create, swap nor make it current on its own.
    m_renderWindow->SetOwnContext(false);
    m_renderWindow->SetReadyForRendering(false);
    m_renderWindow->SetFrameBlitModeToBlitToCurrent();
    m_renderWindow->SetMultiSamples(4);
    m_renderWindow->AddRenderer(m_renderer);

    m_callback->SetClientData(this);
    m_callback->SetCallback(&VtkViewWidget::onVtkEvent);
    m_renderWindow->AddObserver(vtkCommand::WindowMakeCurrentEvent, m_callback);
    m_renderWindow->AddObserver(vtkCommand::WindowIsCurrentEvent, m_callback);
    m_renderWindow->AddObserver(vtkCommand::WindowFrameEvent, m_callback);

    m_interactor->SetRenderWindow(m_renderWindow);
    m_interactor->SetInteractorStyle(m_style);
    // The interactor asks for renders through RenderEvent; we turn those into Qt repaints.
    m_interactor->EnableRenderOff();
    m_interactor->AddObserver(vtkCommand::RenderEvent, m_callback);
    m_interactor->AddObserver(vtkCommand::ExitEvent, m_callback);
    m_interactor->Initialize();

    m_renderer->GradientBackgroundOn();
    m_renderer->SetBackground(0.80, 0.84, 0.89);  // bottom
    m_renderer->SetBackground2(0.98, 0.98, 1.00); // top
    m_renderer->AutomaticLightCreationOff();
    vtkNew<vtkLightKit> lights;
    lights->SetKeyLightIntensity(0.75);
    // A stronger head light than the default: steep faults seen from below the key light stay lit.
    lights->SetKeyToHeadRatio(1.8);
    lights->SetKeyToFillRatio(2.5);
    lights->AddLightsToRenderer(m_renderer);

    vtkNew<vtkAxesActor> axes;
    axes->SetShaftTypeToCylinder();
    axes->SetCylinderRadius(0.03);
    axes->SetConeRadius(0.5);
    axes->SetTotalLength(1.2, 1.2, 1.2);
    axes->SetXAxisLabelText("E");
    axes->SetYAxisLabelText("N");
    axes->SetZAxisLabelText("Z");
    configureAxesLabel(axes->GetXAxisCaptionActor2D());
    configureAxesLabel(axes->GetYAxisCaptionActor2D());
    configureAxesLabel(axes->GetZAxisCaptionActor2D());
    m_axes = vtkSmartPointer<vtkOrientationMarkerWidget>::New();
    m_axes->SetOrientationMarker(axes);
    m_axes->SetInteractor(m_interactor);
    m_axes->SetViewport(0.0, 0.0, 0.14, 0.2);
    m_axes->SetEnabled(1);
    m_axes->InteractiveOff();

    resetCamera();
}

VtkViewWidget::~VtkViewWidget()
{
    // The context outlives this part of the object: its aboutToBeDestroyed must not call us back.
    if (context())
        disconnect(context(), nullptr, this, nullptr);
    m_axes->SetEnabled(0);
    // Free VTK's GL resources while our context still exists.
    makeCurrent();
    cleanupGL();
    doneCurrent();
    m_renderWindow->RemoveObserver(m_callback);
    m_interactor->RemoveObserver(m_callback);
}

QSurfaceFormat VtkViewWidget::defaultFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(0); // VTK does its own multisampling in its framebuffers
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    return format;
}

vtkRenderer *VtkViewWidget::renderer() const
{
    return m_renderer;
}
vtkGenericOpenGLRenderWindow *VtkViewWidget::renderWindow() const
{
    return m_renderWindow;
}
vtkGenericRenderWindowInteractor *VtkViewWidget::interactor() const
{
    return m_interactor;
}

void VtkViewWidget::resetCamera()
{
    applyExaggeration();
    double bounds[6];
    m_renderer->ComputeVisiblePropBounds(bounds); // already exaggerated
    frame(bounds);
}

void VtkViewWidget::setVerticalExaggeration(double factor)
{
    if (!(factor > 0.0) || factor == m_exaggeration)
        return;
    m_exaggeration = factor;
    m_exaggerationMatrix->SetElement(2, 2, factor);
    applyExaggeration();
}

void VtkViewWidget::applyExaggeration()
{
    vtkMatrix4x4 *matrix = m_exaggeration == 1.0 ? nullptr : m_exaggerationMatrix.Get();
    vtkPropCollection *props = m_renderer->GetViewProps();
    vtkCollectionSimpleIterator it;
    props->InitTraversal(it);
    while (vtkProp *prop = props->GetNextProp(it)) {
        auto *prop3d = vtkProp3D::SafeDownCast(prop);
        if (!prop3d || prop3d->GetUserMatrix() == matrix)
            continue;
        prop3d->SetUserMatrix(matrix);
    }
}

void VtkViewWidget::centreOn(const double modelPoint[3])
{
    const double point[3] = {modelPoint[0], modelPoint[1], m_exaggeration * modelPoint[2]};
    vtkCamera *camera = m_renderer->GetActiveCamera();
    double focal[3], position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    camera->SetFocalPoint(point[0], point[1], point[2]);
    camera->SetPosition(position[0] + point[0] - focal[0], position[1] + point[1] - focal[1],
                        position[2] + point[2] - focal[2]);
    m_renderer->ResetCameraClippingRange();
}

void VtkViewWidget::flyTo(const double modelPoint[3], double distance)
{
    centreOn(modelPoint);
    const double point[3] = {modelPoint[0], modelPoint[1], m_exaggeration * modelPoint[2]};
    vtkCamera *camera = m_renderer->GetActiveCamera();
    // vtkCamera::SetDistance would move the focal point: the position moves instead.
    if (distance > 0.0 && camera->GetDistance() > distance) {
        double direction[3];
        camera->GetDirectionOfProjection(direction);
        camera->SetPosition(point[0] - distance * direction[0], point[1] - distance * direction[1],
                            point[2] - distance * direction[2]);
    }
    m_renderer->ResetCameraClippingRange();
}

void VtkViewWidget::resetCamera(const double modelBounds[6])
{
    applyExaggeration();
    double bounds[6];
    std::copy(modelBounds, modelBounds + 6, bounds);
    bounds[4] *= m_exaggeration;
    bounds[5] *= m_exaggeration;
    frame(bounds);
}

void VtkViewWidget::frame(const double bounds[6])
{
    vtkCamera *camera = m_renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    // From the south-west, 30 degrees above the horizon.
    const double elevation = 30.0 * M_PI / 180.0, azimuth = -35.0 * M_PI / 180.0;
    camera->SetPosition(std::sin(azimuth) * std::cos(elevation),
                        -std::cos(azimuth) * std::cos(elevation), std::sin(elevation));
    camera->SetViewUp(0.0, 0.0, 1.0);
    if (bounds[0] <= bounds[1]) {
        m_renderer->ResetCamera(bounds);
        // ResetCamera fits the bounding sphere, which leaves flat models small: fit the box's
        // corners instead, to ~85 % of the view (a few steps, as perspective is not linear).
        for (int step = 0; step < 4; ++step) {
            m_renderer->ResetCameraClippingRange();
            double extent = 0.0;
            for (int corner = 0; corner < 8; ++corner) {
                m_renderer->SetWorldPoint(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
                                          bounds[4 + ((corner >> 2) & 1)], 1.0);
                m_renderer->WorldToView();
                const double *v = m_renderer->GetViewPoint();
                extent = std::max({extent, std::abs(v[0]), std::abs(v[1])});
            }
            if (extent <= 0.0 || std::abs(extent - 0.85) < 0.01)
                break;
            camera->Dolly(0.85 / extent);
        }
    }
    m_renderer->ResetCameraClippingRange();
    render();
}

void VtkViewWidget::render()
{
    update();
}

QSize VtkViewWidget::minimumSizeHint() const
{
    return {320, 240};
}
QSize VtkViewWidget::sizeHint() const
{
    return {900, 650};
}

void VtkViewWidget::initializeGL()
{
    if (m_initialized)
        cleanupGL(); // a new context (the widget was reparented): start from scratch
    // QOpenGLWidget recreates its context on reparenting; VTK must drop resources of the old one.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
            &VtkViewWidget::onContextAboutToBeDestroyed, Qt::UniqueConnection);
    m_renderWindow->SetMapped(1);
    m_renderWindow->SetIsDirect(1);
    m_renderWindow->SetSupportsOpenGL(1);
    m_renderWindow->InitializeFromCurrentContext();
    m_initialized = true;
}

void VtkViewWidget::resizeGL(int w, int h)
{
    const qreal ratio = devicePixelRatioF();
    const int pw = int(std::lround(w * ratio)), ph = int(std::lround(h * ratio));
    m_interactor->UpdateSize(pw, ph); // also sizes the render window
}

void VtkViewWidget::paintGL()
{
    if (!m_initialized)
        return;
    const qreal ratio = devicePixelRatioF();
    const int pw = int(std::lround(width() * ratio)), ph = int(std::lround(height() * ratio));
    int *size = m_renderWindow->GetSize();
    if (size[0] != pw || size[1] != ph)
        m_interactor->UpdateSize(pw, ph);

    // Qt touched the GL state since our last frame: make VTK re-read it, and give it back after.
    vtkOpenGLState *state = m_renderWindow->GetState();
    state->Reset();
    state->Push();
    state->vtkglDepthFunc(GL_LEQUAL); // Qt leaves GL_LESS; VTK expects LEQUAL
    applyExaggeration();
    m_renderWindow->SetReadyForRendering(true);
    m_renderWindow->Render();
    m_renderWindow->SetReadyForRendering(false);
    state->Pop();

    // Translucent actors leave alpha < 1 in the framebuffer; Qt would then blend the view with
    // whatever lies below it when composing the window (washed-out or saturated colours).
    QOpenGLFunctions *gl = context()->functions();
    GLboolean mask[4];
    GLfloat clear[4];
    gl->glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    gl->glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(mask[0], mask[1], mask[2], mask[3]);
    gl->glClearColor(clear[0], clear[1], clear[2], clear[3]);
}

void VtkViewWidget::onContextAboutToBeDestroyed()
{
    makeCurrent();
    cleanupGL();
    doneCurrent();
}

void VtkViewWidget::cleanupGL()
{
    if (!m_initialized)
        return;
    m_renderWindow->SetReadyForRendering(false);
    m_renderWindow->ReleaseGraphicsResources(m_renderWindow);
    m_renderWindow->Finalize();
    m_initialized = false;
}

void VtkViewWidget::onVtkEvent(vtkObject *, unsigned long eventId, void *clientData, void *callData)
{
    auto *self = static_cast<VtkViewWidget *>(clientData);
    switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
        // QOpenGLWidget::makeCurrent() also rebinds Qt's framebuffer, which would silently undo
        // VTK's own binding (VTK asks for this in the middle of binding its framebuffers).
        if (QOpenGLContext::currentContext() != self->context())
            self->makeCurrent();
        break;
    case vtkCommand::WindowIsCurrentEvent: {
        QOpenGLContext *ctx = self->context();
        *static_cast<bool *>(callData) = ctx && QOpenGLContext::currentContext() == ctx;
        break;
    }
    case vtkCommand::RenderEvent:
        self->update();
        emit self->cameraMovedByUser();
        break;
    default: // WindowFrameEvent: Qt swaps; ExitEvent: ignored on purpose
        break;
    }
}

void VtkViewWidget::setPointerInfo(const QPointF &pos, Qt::KeyboardModifiers modifiers)
{
    const qreal ratio = devicePixelRatioF();
    m_interactor->SetEventInformationFlipY(
        int(std::lround(pos.x() * ratio)), int(std::lround(pos.y() * ratio)),
        (modifiers & Qt::ControlModifier) ? 1 : 0, (modifiers & Qt::ShiftModifier) ? 1 : 0);
    m_interactor->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
}

QPointF VtkViewWidget::displayPosition(const QPointF &pos) const
{
    const qreal ratio = devicePixelRatioF();
    return {pos.x() * ratio, height() * ratio - pos.y() * ratio - 1.0};
}

void VtkViewWidget::endHover()
{
    m_hoverTimer.stop();
    if (m_hoverShown) {
        m_hoverShown = false;
        emit hoverEnded();
    }
}

void VtkViewWidget::mousePressEvent(QMouseEvent *event)
{
    endHover();
    if (event->button() == Qt::LeftButton)
        m_leftPress = event->position();
    setPointerInfo(event->position(), event->modifiers());
    if (const int id = vtkButtonEvent(event->button(), true); id != vtkCommand::NoEvent)
        m_interactor->InvokeEvent(id, nullptr);
    event->accept();
}

void VtkViewWidget::mouseReleaseEvent(QMouseEvent *event)
{
    setPointerInfo(event->position(), event->modifiers());
    if (const int id = vtkButtonEvent(event->button(), false); id != vtkCommand::NoEvent)
        m_interactor->InvokeEvent(id, nullptr);
    event->accept();
    // A few pixels of jitter are still a click; more is a rotation of the camera.
    if (event->button() == Qt::LeftButton && m_leftPress.x() >= 0.0
        && (event->position() - m_leftPress).manhattanLength() <= 4.0) {
        const QPointF p = displayPosition(event->position());
        emit clicked(p.x(), p.y());
    }
    m_leftPress = QPointF(-1.0, -1.0);
}

void VtkViewWidget::mouseDoubleClickEvent(QMouseEvent *event)
{
    setPointerInfo(event->position(), event->modifiers());
    m_interactor->SetRepeatCount(1);
    if (const int id = vtkButtonEvent(event->button(), true); id != vtkCommand::NoEvent)
        m_interactor->InvokeEvent(id, nullptr);
    m_interactor->SetRepeatCount(0);
    event->accept();
}

void VtkViewWidget::mouseMoveEvent(QMouseEvent *event)
{
    setPointerInfo(event->position(), event->modifiers());
    m_interactor->InvokeEvent(vtkCommand::MouseMoveEvent, nullptr);
    event->accept();
    endHover();
    if (event->buttons() == Qt::NoButton) {
        m_hoverPos = event->position();
        m_hoverTimer.start();
    }
}

void VtkViewWidget::wheelEvent(QWheelEvent *event)
{
    endHover();
    setPointerInfo(event->position(), event->modifiers());
    const int delta = event->angleDelta().y();
    if (delta > 0)
        m_interactor->InvokeEvent(vtkCommand::MouseWheelForwardEvent, nullptr);
    else if (delta < 0)
        m_interactor->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, nullptr);
    event->accept();
}

void VtkViewWidget::keyPressEvent(QKeyEvent *event)
{
    if (!isForwardedKey(event)) {
        QOpenGLWidget::keyPressEvent(event);
        return;
    }
    const QByteArray text = event->text().toLatin1();
    const char code = text.isEmpty() ? 0 : text.at(0);
    const char *sym = keySym(event->key());
    m_interactor->SetKeyEventInformation((event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                         (event->modifiers() & Qt::ShiftModifier) ? 1 : 0, code,
                                         event->isAutoRepeat() ? 1 : 0,
                                         sym ? sym : text.constData());
    m_interactor->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
    if (code != 0)
        m_interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
    event->accept();
}

void VtkViewWidget::keyReleaseEvent(QKeyEvent *event)
{
    if (!isForwardedKey(event)) {
        QOpenGLWidget::keyReleaseEvent(event);
        return;
    }
    const QByteArray text = event->text().toLatin1();
    const char code = text.isEmpty() ? 0 : text.at(0);
    const char *sym = keySym(event->key());
    m_interactor->SetKeyEventInformation((event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                         (event->modifiers() & Qt::ShiftModifier) ? 1 : 0, code, 0,
                                         sym ? sym : text.constData());
    m_interactor->InvokeEvent(vtkCommand::KeyReleaseEvent, nullptr);
    event->accept();
}

void VtkViewWidget::enterEvent(QEnterEvent *event)
{
    m_interactor->InvokeEvent(vtkCommand::EnterEvent, nullptr);
    QOpenGLWidget::enterEvent(event);
}

void VtkViewWidget::leaveEvent(QEvent *event)
{
    endHover();
    m_interactor->InvokeEvent(vtkCommand::LeaveEvent, nullptr);
    QOpenGLWidget::leaveEvent(event);
}

} // namespace stratamesh
