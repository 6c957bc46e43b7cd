// File > Open Study…: a study run by stratamesh-cli study, shown in its own window (the table, the
// charts and the task views are StudyWindow's). No background run: the table is read at once.
#pragma once

#include "workflow.h"

namespace stratamesh {

class StudyWindow;

class StudyWorkflow : public Workflow {
    Q_OBJECT
public:
    explicit StudyWorkflow(Workbench &bench, QObject *parent = nullptr);

    StudyWindow *studyWindow() const { return m_window; }
    QAction *openAction() const { return m_open; }

    QList<QAction *> menuActions(Menu menu) const override;
    void retranslate() override;

public slots:
    // A .smstudy or a gathered study.json; a message box says what is wrong with it.
    void openStudy(const QString &path);
    void chooseStudy();

private:
    QAction *m_open;
    StudyWindow *m_window = nullptr;
};

} // namespace stratamesh
