#include "task_result_window.h"

#include "ledger_panel.h"
#include "model_scene.h"
#include "vtk_view_widget.h"

#include <QSplitter>
#include <QVBoxLayout>

#include <vtkCamera.h>
#include <vtkRenderer.h>

namespace stratamesh {

TaskResultWindow::TaskResultWindow(QWidget *parent)
    : QWidget(parent, Qt::Window), m_inputView(new VtkViewWidget), m_outputView(new VtkViewWidget),
      m_ledger(new LedgerPanel)
{
    m_inputScene = std::make_unique<ModelScene>(m_inputView->renderer());
    m_outputScene = std::make_unique<ModelScene>(m_outputView->renderer());
    // One camera for both views, as in the main window: what is compared is the same place.
    m_outputView->renderer()->SetActiveCamera(m_inputView->renderer()->GetActiveCamera());
    connect(m_inputView, &VtkViewWidget::cameraMovedByUser, m_outputView, &VtkViewWidget::render);
    connect(m_outputView, &VtkViewWidget::cameraMovedByUser, m_inputView, &VtkViewWidget::render);

    auto *views = new QSplitter(Qt::Horizontal);
    views->addWidget(m_inputView);
    views->addWidget(m_outputView);
    auto *split = new QSplitter(Qt::Vertical);
    split->addWidget(views);
    split->addWidget(m_ledger);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);
    resize(1200, 800);
}

TaskResultWindow::~TaskResultWindow() = default;

void TaskResultWindow::show(const QString &title, std::shared_ptr<const Model> input,
                            std::shared_ptr<const Model> output, SimplificationLedger ledger)
{
    setWindowTitle(title);
    m_inputScene->setModel(std::move(input));
    m_outputScene->setModel(std::move(output));
    m_ledger->setLedger(std::make_shared<const SimplificationLedger>(std::move(ledger)));
    double bounds[6];
    if (m_inputScene->bounds(bounds))
        m_inputView->resetCamera(bounds);
    m_inputView->render();
    m_outputView->render();
    QWidget::show();
    raise();
}

} // namespace stratamesh
