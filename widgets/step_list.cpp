#include "step_list.h"

#include <QAction>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace stratamesh {

StepList::StepList(QWidget *parent) : QWidget(parent), m_layout(new QVBoxLayout(this))
{
    m_layout->setContentsMargins(4, 4, 4, 4);
    m_layout->addStretch(1);
}

int StepList::addStep(const QList<QAction *> &actions)
{
    auto *frame = new QFrame(this);
    frame->setFrameShape(QFrame::StyledPanel);
    auto *layout = new QVBoxLayout(frame);
    layout->setContentsMargins(6, 4, 6, 4);
    Step step;
    step.title = new QLabel(frame);
    QFont bold = step.title->font();
    bold.setBold(true);
    step.title->setFont(bold);
    step.status = new QLabel(frame);
    step.status->setWordWrap(true);
    step.status->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    step.actions = actions;
    layout->addWidget(step.title);
    layout->addWidget(step.status);
    auto *buttons = new QHBoxLayout;
    for (QAction *action : actions) {
        auto *button = new QToolButton(frame);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        buttons->addWidget(button);
    }
    buttons->addStretch(1);
    layout->addLayout(buttons);
    frame->setObjectName(QStringLiteral("Step%1").arg(m_steps.size() + 1));
    m_layout->insertWidget(m_layout->count() - 1, frame);
    m_steps.append(step);
    return int(m_steps.size()) - 1;
}

void StepList::setTitle(int step, const QString &title)
{
    m_steps[step].titleText = title;
    showTitle(step);
}

void StepList::setStatus(int step, const QString &status, bool done)
{
    m_steps[step].status->setText(status);
    m_steps[step].done = done;
    showTitle(step);
}

QString StepList::titleText(int step) const
{
    return m_steps.at(step).title->text();
}

QString StepList::statusText(int step) const
{
    return m_steps.at(step).status->text();
}

void StepList::showTitle(int step)
{
    const Step &s = m_steps.at(step);
    // "2. Complexity ✓": the number gives the order, the mark what is done.
    s.title->setText(QStringLiteral("%1. %2%3")
                         .arg(step + 1)
                         .arg(s.titleText, s.done ? QStringLiteral("  ✓") : QString()));
}

} // namespace stratamesh
