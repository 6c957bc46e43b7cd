#include "study_workflow.h"

#include "error_message.h"
#include "study_window.h"
#include "workbench.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>

namespace stratamesh {

StudyWorkflow::StudyWorkflow(Workbench &bench, QObject *parent)
    : Workflow(bench, parent), m_open(new QAction(this))
{
    connect(m_open, &QAction::triggered, this, &StudyWorkflow::chooseStudy);
}

QList<QAction *> StudyWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::File)
        return {m_open};
    return {};
}

void StudyWorkflow::retranslate()
{
    m_open->setText(tr("Open S&tudy…"));
    m_open->setStatusTip(
        tr("Show the table of a study run by stratamesh-cli study (.smstudy or study.json)"));
}

void StudyWorkflow::chooseStudy()
{
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastStudyDirectory")).toString();
    const QString path = QFileDialog::getOpenFileName(
        m_bench.window(), tr("Open Study"), dir,
        tr("StrataMesh studies (*.smstudy);;Gathered study tables (study.json)"));
    if (path.isEmpty())
        return;
    settings.setValue(QStringLiteral("lastStudyDirectory"), QFileInfo(path).absolutePath());
    openStudy(path);
}

void StudyWorkflow::openStudy(const QString &path)
{
    if (!m_window) {
        m_window = new StudyWindow(m_bench.window());
        m_window->setWindowFlag(Qt::Window);
    }
    try {
        m_window->openStudy(path);
    } catch (const std::exception &e) {
        QMessageBox::warning(m_bench.window(), tr("Cannot open the study"),
                             errorMessage(e, path).text);
        return;
    }
    m_window->show();
    m_window->raise();
}

} // namespace stratamesh
