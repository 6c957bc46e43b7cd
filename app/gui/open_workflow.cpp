#include "open_workflow.h"

#include "app_settings.h"
#include "error_message.h"
#include "message_panel.h"
#include "open_model_controller.h"
#include "workbench.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QStyle>

namespace stratamesh {

OpenWorkflow::OpenWorkflow(Workbench &bench, QObject *parent)
    : Workflow(bench, parent), m_controller(new OpenModelController(this)),
      m_open(new QAction(this)), m_openSample(new QAction(this))
{
    m_open->setShortcut(QKeySequence::Open);
    m_open->setIcon(
        QIcon::fromTheme(QStringLiteral("document-open"),
                         m_bench.window()->style()->standardIcon(QStyle::SP_DialogOpenButton)));
    connect(m_open, &QAction::triggered, this, &OpenWorkflow::chooseFile);
    connect(m_openSample, &QAction::triggered, this, &OpenWorkflow::openSample);

    connect(m_controller, &OpenModelController::opening, this, &OpenWorkflow::onOpening);
    connect(m_controller, &OpenModelController::loaded, this, &OpenWorkflow::onLoaded);
    connect(m_controller, &OpenModelController::failed, this, &OpenWorkflow::onFailed);
    relay(m_controller);
}

QList<QAction *> OpenWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::File)
        return {m_open, m_openSample};
    return {};
}

QList<QAction *> OpenWorkflow::toolBarActions() const
{
    return {m_open};
}

WorkflowJob *OpenWorkflow::job() const
{
    return m_controller;
}

void OpenWorkflow::retranslate()
{
    m_open->setText(tr("&Open Model…"));
    m_open->setStatusTip(tr("Open a structural model file"));
    m_openSample->setText(tr("Open &Sample Model"));
    m_openSample->setStatusTip(tr("Show the synthetic model bundled with StrataMesh"));
}

void OpenWorkflow::enableActions(bool busy)
{
    m_open->setEnabled(!busy);
    m_openSample->setEnabled(!busy);
}

// What was made of the shown model goes with it: an unsaved result is offered for saving first.
void OpenWorkflow::openFile(const QString &path)
{
    if (m_bench.mayDiscardWork())
        m_controller->openFile(path);
}

void OpenWorkflow::openSample()
{
    if (m_bench.mayDiscardWork())
        m_controller->openSample();
}

void OpenWorkflow::chooseFile()
{
    const std::unique_ptr<QSettings> settings = openSettings();
    const QString dir = settings->value(QStringLiteral("lastDirectory")).toString();
    const QString path = QFileDialog::getOpenFileName(m_bench.window(), tr("Open Model"), dir,
                                                      OpenModelController::fileFilter());
    if (path.isEmpty())
        return;
    settings->setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    openFile(path);
}

void OpenWorkflow::onOpening(const QString &displayName)
{
    m_bench.setStatus(tr("Opening %1…").arg(displayName));
}

void OpenWorkflow::onLoaded(const LoadedModel &loaded)
{
    m_bench.messages()->clear();
    emit opened(loaded);

    Message opened;
    opened.text =
        tr("%1 opened in %2 s")
            .arg(loaded.displayName, QLocale().toString(loaded.milliseconds / 1000.0, 'f', 2));
    opened.file = loaded.path;
    m_bench.addMessage(opened);
    for (const Message &m : loaded.messages)
        m_bench.addMessage(m);
    if (loaded.messages.empty()) {
        Message valid;
        valid.text = tr("No validity problem found");
        valid.file = loaded.path;
        m_bench.addMessage(valid);
    } else {
        m_bench.showMessages(false);
    }
    m_bench.setStatus(loaded.messages.empty() ? tr("Ready")
                                              : tr("%n validity problem(s) — see Messages", nullptr,
                                                   int(loaded.messages.size())));
}

void OpenWorkflow::onFailed(const Message &error)
{
    m_bench.messages()->clear();
    m_bench.addMessage(error);
    m_bench.showMessages();
    const QString where = formatLocation(error);
    m_bench.setStatus(where.isEmpty() ? tr("Could not open the model")
                                      : tr("Could not open %1").arg(where));
}

} // namespace stratamesh
