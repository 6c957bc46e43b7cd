// View > Colour By, Clip Plane and Next Worst Triangle: how both views draw the models (issue 17).
// The colouring (entity, min angle, Q, distance to the other model) is the same in both views with
// the same range, bad always at the warm end; each choice is undoable. One clip plane cuts the
// surfaces and the tet meshes of both views. A click on a histogram bar of Input vs Output
// highlights that bin's triangles, and Next Worst flies to the triangles by increasing Q.
#pragma once

#include "tet_mesh_pair.h"
#include "workflow.h"

#include "quality/triangle_measures.h"

#include <optional>
#include <vector>

class QActionGroup;
class QMenu;
class QSlider;
class QWidgetAction;

namespace stratamesh {

class HybridWorkflow;
class RemeshWorkflow;
class TetmeshWorkflow;

enum class Colouring { Entity, MinAngle, Quality, Distance };

struct ColourChoice {
    Colouring colouring = Colouring::Entity;
    bool reverse = false;
    bool operator==(const ColourChoice &o) const
    {
        return colouring == o.colouring && reverse == o.reverse;
    }
    bool operator!=(const ColourChoice &o) const { return !(*this == o); }
};

struct ClipState {
    bool enabled = false;
    ClipAxis axis = ClipAxis::Y;
    double fraction = 0.5;
    bool operator==(const ClipState &o) const
    {
        return enabled == o.enabled && axis == o.axis && fraction == o.fraction;
    }
    bool operator!=(const ClipState &o) const { return !(*this == o); }
};

class ViewWorkflow : public Workflow {
    Q_OBJECT
public:
    ViewWorkflow(Workbench &bench, RemeshWorkflow &remesh, TetmeshWorkflow &tetmesh,
                 HybridWorkflow &hybrid, QObject *parent = nullptr);

    QList<QAction *> menuActions(Menu menu) const override;
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;

    const ColourChoice &colourChoice() const { return m_choice; }
    // As the user does: pushes an undoable command unless nothing changes.
    void chooseColouring(Colouring colouring);
    void chooseReverse(bool reverse);
    // Draws both views so (the undo command's work; no command).
    void applyColourChoice(const ColourChoice &choice);
    // The tet meshes' colouring that goes with it (min dihedral for min angle and Q).
    void applyTetColouring(const ColourChoice &choice);
    QAction *colourAction(Colouring colouring) const;
    QAction *reverseAction() const { return m_reverse; }

    // As the user does: an undoable command (moves of the position merge into one).
    void chooseClip(bool enabled, ClipAxis axis, double fraction);
    // `fraction` in [0, 1] across the bounds of both models together, as the tet meshes' clip
    // (the command's work; no command).
    void setClip(bool enabled, ClipAxis axis, double fraction);
    bool clipEnabled() const { return m_clipEnabled; }
    QAction *clipAction() const { return m_clip; }

    // Highlights the triangles of a bin of the Q (`quality`) or min angle histogram, of the
    // output or the input; returns how many (the bar's count).
    int selectBin(bool quality, int bin, bool output);
    int selectionCount() const { return m_selectionCount; }

    // Flies to the next triangle by increasing Q, of the output (the input when there is none),
    // box triangles only while the box is shown, and highlights it.
    void nextWorst();
    QAction *nextWorstAction() const { return m_nextWorst; }
    // Removes the highlight (and the marker) from both views.
    void clearHighlight();
    QAction *clearHighlightAction() const { return m_clearHighlight; }
    // The triangle Next Worst went to last; nullopt before.
    std::optional<MeasuredTriangle> lastWorst() const;

private:
    void applyClip();
    void resetReview();
    void connectCharts();
    std::shared_ptr<const Model> output() const;

    RemeshWorkflow &m_remesh;
    TetmeshWorkflow &m_tetmesh;
    HybridWorkflow &m_hybrid;
    ColourChoice m_choice;
    std::vector<std::vector<double>> m_inputDistance; // cache: input vertices to the output
    QMenu *m_colourMenu;
    QActionGroup *m_colourGroup;
    QAction *m_colourActions[4];
    QAction *m_reverse;
    QMenu *m_clipMenu;
    QAction *m_clip;
    QActionGroup *m_axisGroup;
    QAction *m_axisActions[3];
    QWidgetAction *m_positionAction;
    QSlider *m_position;
    bool m_clipEnabled = false;
    ClipAxis m_axis = ClipAxis::Y;
    double m_fraction = 0.5;
    bool m_syncing = false; // while the tet panels are told the plane
    QAction *m_nextWorst;
    QAction *m_clearHighlight;
    QAction *m_separator;
    std::vector<MeasuredTriangle> m_worst; // by increasing Q, computed at the first Next Worst
    int m_worstNext = 0;
    bool m_worstOfOutput = false;
    bool m_worstWithBox = false;
    int m_selectionCount = 0;
};

} // namespace stratamesh
