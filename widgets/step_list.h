// The workflow as numbered steps (Check → Complexity → Remesh → Volume → Export): each with its
// title, what has been done so far, and buttons for the menu actions that do it. The buttons are
// the actions themselves (enabled, tooltip and text follow them), so the panel starts nothing of
// its own.
#pragma once

#include <QList>
#include <QWidget>

class QAction;
class QLabel;
class QVBoxLayout;

namespace stratamesh {

class StepList : public QWidget {
    Q_OBJECT
public:
    explicit StepList(QWidget *parent = nullptr);

    // Returns the step's index.
    int addStep(const QList<QAction *> &actions);
    int count() const { return int(m_steps.size()); }
    void setTitle(int step, const QString &title);
    // `done`: the step has a result (its title gets a check mark).
    void setStatus(int step, const QString &status, bool done);

    QString titleText(int step) const;
    QString statusText(int step) const;
    bool isDone(int step) const { return m_steps.at(step).done; }
    QList<QAction *> actions(int step) const { return m_steps.at(step).actions; }

private:
    struct Step {
        QLabel *title = nullptr;
        QLabel *status = nullptr;
        QList<QAction *> actions;
        QString titleText;
        bool done = false;
    };
    void showTitle(int step);

    QVBoxLayout *m_layout;
    QList<Step> m_steps;
};

} // namespace stratamesh
