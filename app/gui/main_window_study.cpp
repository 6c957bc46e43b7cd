// File > Open Study…: MainWindow only opens the study window; the table, the charts and the task
// views are StudyWindow's.
#include "main_window.h"
#include "study_window.h"

#include "error_message.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>

namespace stratamesh {

void MainWindow::chooseStudy()
{
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastStudyDirectory")).toString();
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Study"), dir,
        tr("StrataMesh studies (*.smstudy);;Gathered study tables (study.json)"));
    if (path.isEmpty())
        return;
    settings.setValue(QStringLiteral("lastStudyDirectory"), QFileInfo(path).absolutePath());
    openStudy(path);
}

void MainWindow::openStudy(const QString &path)
{
    if (!m_studyWindow) {
        m_studyWindow = new StudyWindow(this);
        m_studyWindow->setWindowFlag(Qt::Window);
    }
    try {
        m_studyWindow->openStudy(path);
    } catch (const std::exception &e) {
        QMessageBox::warning(this, tr("Cannot open the study"), errorMessage(e, path).text);
        return;
    }
    m_studyWindow->show();
    m_studyWindow->raise();
}

} // namespace stratamesh
