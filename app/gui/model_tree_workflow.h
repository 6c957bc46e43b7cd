// The Model dock (left): the open model's regions, surfaces, lines and corners as a tree, with a
// visibility check box per surface and group (each change undoable on the Workbench's stack), a
// search by name and the Show Box toggle. Selecting a row highlights the entity in the input view
// and, matched by surface name, in the output view; a click on a triangle in either view tells
// its surface, id and shape (min angle, Q) in the status bar and selects the surface.
#pragma once

#include "workflow.h"

#include <QModelIndex>

#include <memory>
#include <optional>

namespace stratamesh {

class EntityHighlight;
class ModelTreePanel;
class OpenWorkflow;
class RemeshWorkflow;

class ModelTreeWorkflow : public Workflow {
    Q_OBJECT
public:
    ModelTreeWorkflow(Workbench &bench, OpenWorkflow &open, RemeshWorkflow &remesh,
                      QObject *parent = nullptr);
    ~ModelTreeWorkflow() override;

    ModelTreePanel *panel() const { return m_panel; }
    QDockWidget *dock() const { return m_dock; }
    EntityHighlight *inputHighlight() const { return m_inputHighlight.get(); }
    EntityHighlight *outputHighlight() const { return m_outputHighlight.get(); }

    QList<Dock> docks() const override;
    void retranslate() override;
    void clear() override;

    // Shows or hides input surfaces in both views and ticks the tree, without an undo step: the
    // undo commands call it.
    void applySurfacesVisible(const QList<int> &surfaces, bool visible);
    // What lies at display position (x, y) of the input or the output view: its surface selected,
    // the triangle described in the status bar. False when no surface is there.
    bool inspect(bool output, double x, double y);
    // The same description as a tooltip at that place, selecting nothing (the pointer rests
    // there); returns it, empty when no surface is there (any tooltip shown is then hidden).
    QString hover(bool output, double x, double y);

public slots:
    // Lists the Workbench's model (after it was opened).
    void refresh();

private:
    struct Description {
        QString text;
        int inputSurface = -1; // the surface in the tree (the input's), -1 when it has none
    };
    std::optional<Description> describe(bool output, double x, double y) const;
    void requestVisibility(const QList<int> &surfaces, bool visible);
    void onSelected(const QModelIndex &index);
    void highlightOutput(const QModelIndex &index);
    void applyOutputVisibility();
    int outputSurface(int inputSurface) const;

    ModelTreePanel *m_panel;
    QDockWidget *m_dock;
    std::unique_ptr<EntityHighlight> m_inputHighlight;
    std::unique_ptr<EntityHighlight> m_outputHighlight;
};

} // namespace stratamesh
