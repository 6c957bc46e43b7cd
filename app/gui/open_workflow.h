// File > Open Model… and Open Sample Model: OpenModelController reads the model, recovers its
// topology and checks it in a worker thread; this lists what the check found once the window
// shows the model.
#pragma once

#include "loaded_model.h"
#include "workflow.h"

namespace stratamesh {

class OpenModelController;

class OpenWorkflow : public Workflow {
    Q_OBJECT
public:
    explicit OpenWorkflow(Workbench &bench, QObject *parent = nullptr);

    OpenModelController *controller() const { return m_controller; }
    QAction *openAction() const { return m_open; }
    QAction *openSampleAction() const { return m_openSample; }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<QAction *> toolBarActions() const override;
    WorkflowJob *job() const override;
    void retranslate() override;
    void enableActions(bool busy) override;

public slots:
    void openFile(const QString &path);
    void openSample();
    void chooseFile();

signals:
    // A model was read, before its messages are listed: the window shows it in place of the last.
    void opened(const stratamesh::LoadedModel &loaded);

private:
    void onOpening(const QString &displayName);
    void onLoaded(const LoadedModel &loaded);
    void onFailed(const Message &error);

    OpenModelController *m_controller;
    QAction *m_open;
    QAction *m_openSample;
};

} // namespace stratamesh
