#include "view_pair.h"

#include "vtk_view_widget.h"

#include <QLabel>
#include <QVBoxLayout>

#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

namespace stratamesh {

ViewPair::ViewPair(QWidget *parent)
    : QSplitter(Qt::Horizontal, parent), m_input(new VtkViewWidget(this)),
      m_output(new VtkViewWidget(this)), m_inputTitle(new QLabel(this)),
      m_outputTitle(new QLabel(this))
{
    const auto pane = [this](QLabel *title, VtkViewWidget *view) {
        auto *widget = new QWidget(this);
        auto *layout = new QVBoxLayout(widget);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(2);
        title->setAlignment(Qt::AlignCenter);
        layout->addWidget(title);
        layout->addWidget(view, 1);
        return widget;
    };
    m_inputTitle->setObjectName(QStringLiteral("InputViewTitle"));
    m_outputTitle->setObjectName(QStringLiteral("OutputViewTitle"));
    addWidget(pane(m_inputTitle, m_input));
    m_outputPane = pane(m_outputTitle, m_output);
    addWidget(m_outputPane);
    setChildrenCollapsible(false);
    m_outputPane->hide();
    m_inputTitle->hide();

    m_output->renderer()->SetActiveCamera(m_input->renderer()->GetActiveCamera());
    connect(m_input, &VtkViewWidget::cameraMovedByUser, m_output, &VtkViewWidget::render);
    connect(m_output, &VtkViewWidget::cameraMovedByUser, m_input, &VtkViewWidget::render);
}

void ViewPair::setOutputShown(bool shown)
{
    m_outputPane->setVisible(shown);
    m_inputTitle->setVisible(shown);
}

void ViewPair::setTitles(const QString &input, const QString &output)
{
    m_inputTitle->setText(input);
    m_outputTitle->setText(output);
}

void ViewPair::splitEvenly()
{
    const int half = width() / 2;
    setSizes({half, width() - half});
}

void ViewPair::setVerticalExaggeration(double factor)
{
    const double before = m_input->verticalExaggeration();
    if (!(factor > 0.0) || factor == before)
        return;
    // World z is exaggeration × model z: the focal point moves with the model point it shows,
    // and the camera keeps its direction and distance.
    for (VtkViewWidget *view : {m_input, m_output}) {
        if (view == m_output && camerasLinked())
            break;
        vtkCamera *camera = view->renderer()->GetActiveCamera();
        double focal[3], position[3];
        camera->GetFocalPoint(focal);
        camera->GetPosition(position);
        const double shift = focal[2] * (factor / before - 1.0);
        camera->SetFocalPoint(focal[0], focal[1], focal[2] + shift);
        camera->SetPosition(position[0], position[1], position[2] + shift);
    }
    m_input->setVerticalExaggeration(factor);
    m_output->setVerticalExaggeration(factor);
    m_input->renderer()->ResetCameraClippingRange();
    m_output->renderer()->ResetCameraClippingRange();
    m_input->render();
    m_output->render();
}

void ViewPair::setCamerasLinked(bool linked)
{
    if (linked == camerasLinked())
        return;
    vtkCamera *input = m_input->renderer()->GetActiveCamera();
    if (linked) {
        m_output->renderer()->SetActiveCamera(input);
    } else {
        vtkNew<vtkCamera> own;
        own->DeepCopy(input);
        m_output->renderer()->SetActiveCamera(own);
    }
    m_output->renderer()->ResetCameraClippingRange();
    m_output->render();
}

bool ViewPair::camerasLinked() const
{
    return m_output->renderer()->GetActiveCamera() == m_input->renderer()->GetActiveCamera();
}

double ViewPair::verticalExaggeration() const
{
    return m_input->verticalExaggeration();
}

} // namespace stratamesh
