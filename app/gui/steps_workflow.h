// The Steps dock: the workflow in the order a geologist follows it — Check (the open model's
// validity) → Complexity → Remesh → Volume (TetGen, hybrid) → Export — each step with what has
// been done and the buttons of the menu actions that do it. It only shows the other workflows'
// state and actions.
#pragma once

#include "workflow.h"

class QDockWidget;

namespace stratamesh {

class ComplexityWorkflow;
class ExportWorkflow;
class HybridWorkflow;
class OpenWorkflow;
class RemeshWorkflow;
class StepList;
class TetmeshWorkflow;
struct LoadedModel;

class StepsWorkflow : public Workflow {
    Q_OBJECT
public:
    enum Step { Check, Complexity, Remesh, Volume, Export, StepCount };

    StepsWorkflow(Workbench &bench, OpenWorkflow &open, ComplexityWorkflow &complexity,
                  RemeshWorkflow &remesh, TetmeshWorkflow &tetmesh, HybridWorkflow &hybrid,
                  ExportWorkflow &exporter, QObject *parent = nullptr);

    StepList *steps() const { return m_steps; }
    QDockWidget *dock() const { return m_dock; }

    QList<Dock> docks() const override;
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;

private:
    void onOpened(const LoadedModel &loaded);
    void refresh();

    OpenWorkflow &m_open;
    ComplexityWorkflow &m_complexity;
    RemeshWorkflow &m_remesh;
    TetmeshWorkflow &m_tetmesh;
    HybridWorkflow &m_hybrid;
    StepList *m_steps;
    QDockWidget *m_dock;
    QAction *m_showProblems;
    int m_problems = -1; // validity problems of the open model; -1 before one is open
};

} // namespace stratamesh
