// Mesh > Hybrid Mesh… (thesis chapter 5): the dialog, the run (HybridController) on the open
// model, the Hybrid Mesh dock, the mixed cells drawn in the output view (by type, quality or
// region, with the clip plane of the Tetrahedra dock), and File > Save Hybrid Mesh As….
// The output view holds one drawing at a time: a hybrid mesh replaces the TetGen meshes, and a
// new tetrahedralisation or remesh takes the view back (the hybrid mesh stays for saving).
#pragma once

#include "hybrid_outcome.h"
#include "workflow.h"

#include <memory>
#include <optional>

namespace stratamesh {

class HybridController;
class HybridPanel;
class RemeshWorkflow;
class TetMeshPair;
class TetmeshWorkflow;

class HybridWorkflow : public Workflow {
    Q_OBJECT
public:
    HybridWorkflow(Workbench &bench, const RemeshWorkflow &remesh, TetmeshWorkflow &tetmesh,
                   QObject *parent = nullptr);
    // Stops a running mesher (and its TetGen helper).
    ~HybridWorkflow() override;

    HybridController *controller() const { return m_controller; }
    // The last mesh made for this model, if any: a cancelled or failed run leaves it.
    const std::optional<HybridOutcome> &outcome() const { return m_outcome; }
    HybridPanel *panel() const { return m_panel; }
    TetMeshPair *scenes() const { return m_scenes.get(); }
    QAction *hybridAction() const { return m_hybrid; }
    QAction *saveAction() const { return m_save; }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<Dock> docks() const override;
    WorkflowJob *job() const override;
    QAction *cancelAction() const override { return m_cancel; }
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;

public slots:
    // Opens the dialog, then builds the mesh.
    void buildMesh();
    // False when it cannot start.
    bool start(const HybridParams &params);
    // Asks for a .vtu or .msh file name, then saves.
    void chooseFile();
    // Through an output plan (io/output_plan.h): checked first, written whole or not at all;
    // false (and a message) on failure.
    bool save(const QString &path);

private:
    void onStarted();
    void onBuilt(const HybridOutcome &outcome);
    void onFailed(const Message &error);
    void onCancelled();
    void showMesh();
    void hideMesh();
    void applyView();
    void updateTitles();

    const RemeshWorkflow &m_remesh;
    TetmeshWorkflow &m_tetmesh;
    HybridController *m_controller;
    std::optional<HybridOutcome> m_outcome;
    std::optional<HybridParams> m_lastParams;
    std::unique_ptr<TetMeshPair> m_scenes;
    HybridPanel *m_panel;
    QDockWidget *m_dock;
    QAction *m_separator;
    QAction *m_hybrid;
    QAction *m_cancel;
    QAction *m_save;
};

} // namespace stratamesh
