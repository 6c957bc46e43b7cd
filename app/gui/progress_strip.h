// The status bar's run display, shared by every workflow: what the window is doing or did last
// and, while a run is under way, its progress bar and the Cancel button of the workflow running.
// The stage label is a widget of its own: the status bar hides it under a status tip, while the
// bar and Cancel (this widget, a permanent one) stay in reach.
#pragma once

#include <QPointer>
#include <QWidget>

class QAction;
class QLabel;
class QProgressBar;
class QToolButton;

namespace stratamesh {

class WorkflowJob;

class ProgressStrip : public QWidget {
    Q_OBJECT
public:
    explicit ProgressStrip(QWidget *parent = nullptr);

    QLabel *stageLabel() const { return m_stage; }
    void setText(const QString &text);
    QString text() const;
    QProgressBar *progressBar() const { return m_progress; }

    // From now on shows the job's progress, with `cancel` (if any) as the Cancel button.
    void follow(WorkflowJob *job, QAction *cancel);
    // The run has ended: bar and button go, the text stays (it tells how the run ended).
    void release();

private:
    void setProgress(int percent, const QString &stage);

    QLabel *m_stage = nullptr;
    QProgressBar *m_progress = nullptr;
    QToolButton *m_cancel = nullptr;
    QPointer<WorkflowJob> m_job;
};

} // namespace stratamesh
