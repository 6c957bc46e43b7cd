// The scripted steps of the command line (gui_options.h) done on the main window as a user would
// through its workflows, one after the other: each waits for the run before it to finish.
#pragma once

#include "gui_options.h"

#include <QObject>

#include <vector>

namespace stratamesh {

class MainWindow;

class ScriptRunner : public QObject {
    Q_OBJECT
public:
    ScriptRunner(MainWindow &window, std::vector<ScriptStep> steps, QObject *parent = nullptr);

    // Once the model is shown: does the first step (finished(true) at once when there is none).
    void start();
    // Why the last run stopped, naming the step ("step 2 (--run remesh --sites 300) failed: …");
    // empty after a success.
    const QString &failure() const { return m_failure; }

signals:
    void stepFinished(int index);
    // Every step done (true), or the first that failed (false, failure() says which).
    void finished(bool ok);

private:
    void runStep();
    // A run started by runStep() ended.
    void onStepEnded(bool ok);
    void fail(const QString &cause);
    QString lastError() const;

    MainWindow &m_window;
    std::vector<ScriptStep> m_steps;
    int m_next = 0;
    int m_messagesBefore = 0; // in the Messages dock when the step started
    QString m_failure;
};

} // namespace stratamesh
