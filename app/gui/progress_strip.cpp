#include "progress_strip.h"

#include "workflow_job.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

#include <algorithm>

namespace stratamesh {

ProgressStrip::ProgressStrip(QWidget *parent)
    : QWidget(parent), m_stage(new QLabel(parent)), m_progress(new QProgressBar(this)),
      m_cancel(new QToolButton(this))
{
    setObjectName(QStringLiteral("ProgressStrip"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_progress);
    layout->addWidget(m_cancel);
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(180);
    m_progress->setTextVisible(false);
    m_progress->hide();
    m_cancel->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_cancel->setAutoRaise(true);
    m_cancel->hide();
    // As tall with the bar hidden as shown: the views above keep their size when a run ends.
    setMinimumHeight(std::max(m_progress->sizeHint().height(), m_cancel->sizeHint().height()));
}

void ProgressStrip::setText(const QString &text)
{
    m_stage->setText(text);
}

QString ProgressStrip::text() const
{
    return m_stage->text();
}

void ProgressStrip::follow(WorkflowJob *job, QAction *cancel)
{
    if (m_job != job) {
        if (m_job)
            disconnect(m_job, nullptr, this, nullptr);
        m_job = job;
        connect(job, &WorkflowJob::progressChanged, this, &ProgressStrip::setProgress);
        m_progress->setValue(0);
    }
    m_progress->show();
    if (cancel)
        m_cancel->setDefaultAction(cancel);
    m_cancel->setVisible(cancel != nullptr);
}

void ProgressStrip::release()
{
    if (m_job)
        disconnect(m_job, nullptr, this, nullptr);
    m_job = nullptr;
    m_progress->hide();
    m_cancel->hide();
}

void ProgressStrip::setProgress(int percent, const QString &stage)
{
    m_progress->setValue(percent);
    if (!stage.isEmpty())
        m_stage->setText(stage + QStringLiteral("…"));
}

} // namespace stratamesh
