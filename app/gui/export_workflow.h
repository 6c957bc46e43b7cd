// File > Export…: the open model, its remesh, the TetGen meshes of both or the hybrid mesh, to any
// format the core writes (io/formats.h: one table for this dialog and `stratamesh-cli convert`),
// with the writer's options, written in the background (ExportController) through the command
// line's output rules; the result or the error, with its file and cause, goes to Messages.
#pragma once

#include "export_dialog.h"
#include "message.h"
#include "workflow.h"

namespace stratamesh {

class ExportController;
class HybridWorkflow;
class RemeshWorkflow;
class TetmeshWorkflow;

class ExportWorkflow : public Workflow {
    Q_OBJECT
public:
    // The entries of the dialog, in its order.
    enum class Subject { InputModel, RemeshedModel, InputTets, RemeshTets, HybridMesh };

    // An export of the remesh to a format that keeps all of it counts as its save.
    ExportWorkflow(Workbench &bench, RemeshWorkflow &remesh, const TetmeshWorkflow &tetmesh,
                   const HybridWorkflow &hybrid, QObject *parent = nullptr);
    ~ExportWorkflow() override;

    ExportController *controller() const { return m_controller; }
    QAction *exportAction() const { return m_export; }
    // What can be exported now, one entry per Subject, with why not for those that cannot.
    QList<ExportSubject> subjects() const;

    QList<QAction *> menuActions(Menu menu) const override;
    WorkflowJob *job() const override;
    void retranslate() override;
    void enableActions(bool busy) override;

public slots:
    // Opens the dialog, then exports what it was given.
    void chooseExport();
    // Writes `subject` to `path` (format from the extension); false, with a message, when it
    // cannot start (nothing to export, a format that does not take it). finished() follows.
    bool start(stratamesh::ExportWorkflow::Subject subject, const QString &path,
               const ExportOptions &options = {});

private:
    void onSucceeded(const QString &path, const QString &format, qulonglong untaggedSkipped,
                     qint64 milliseconds);
    void onFailed(const Message &error);
    void refuse(const QString &path, const QString &cause);

    RemeshWorkflow &m_remesh;
    const TetmeshWorkflow &m_tetmesh;
    const HybridWorkflow &m_hybrid;
    ExportController *m_controller;
    QAction *m_separator;
    QAction *m_export;
    bool m_savesRemesh = false; // the run under way writes all of the remesh
};

} // namespace stratamesh
