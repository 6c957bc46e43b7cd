// Mesh > Tetrahedralise… (thesis §5.2): the TetGen dialog, the run (TetmeshController) on the
// input and on the remesh, the Tetrahedra dock, and the tets drawn in place of the surfaces in
// both views.
#pragma once

#include "tetmesh_outcome.h"
#include "workflow.h"

#include <memory>
#include <optional>

namespace stratamesh {

class RemeshWorkflow;
class TetMeshPair;
class TetmeshController;
class TetmeshPanel;

class TetmeshWorkflow : public Workflow {
    Q_OBJECT
public:
    // The remesh is the other side of the comparison: a new one drops the meshes shown.
    TetmeshWorkflow(Workbench &bench, const RemeshWorkflow &remesh, QObject *parent = nullptr);
    // Kills a running TetGen helper.
    ~TetmeshWorkflow() override;

    TetmeshController *controller() const { return m_controller; }
    // The last meshes shown, if any (cleared by another model or another remesh).
    const std::optional<TetmeshOutcome> &outcome() const { return m_outcome; }
    TetmeshPanel *panel() const { return m_panel; }
    TetMeshPair *scenes() const { return m_scenes.get(); }
    QAction *tetmeshAction() const { return m_tetmesh; }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<Dock> docks() const override;
    WorkflowJob *job() const override;
    QAction *cancelAction() const override { return m_cancel; }
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;

public slots:
    // Opens the TetGen dialog, then tetrahedralises the input and, by default, the remesh.
    void tetrahedralise();
    // With these switches, the remesh too when `withRemesh` and there is one; false when it
    // cannot start.
    bool start(const TetgenParams &params, bool withRemesh);

private:
    void onStarted();
    void onTetmeshed(const TetmeshOutcome &outcome);
    void onFailed(const Message &error);
    void onCancelled();
    void applyTetView();

    const RemeshWorkflow &m_remesh;
    TetmeshController *m_controller;
    std::optional<TetmeshOutcome> m_outcome;
    std::optional<TetgenParams> m_lastParams;
    std::unique_ptr<TetMeshPair> m_scenes;
    TetmeshPanel *m_panel;
    QDockWidget *m_dock;
    QAction *m_separator;
    QAction *m_tetmesh;
    QAction *m_cancel;
};

} // namespace stratamesh
