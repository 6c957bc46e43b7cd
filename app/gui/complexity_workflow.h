// Analyse > Complexity… (thesis ch. 3): the dialog, the run (ComplexityController), the Complexity
// dock and the heat map of elements per cell in the input view (Fig 3.7); Analyse > Export
// Complexity Cells….
#pragma once

#include "complexity_outcome.h"
#include "workflow.h"

#include <memory>
#include <optional>

namespace stratamesh {

class CellHeatMap;
class ComplexityController;
class ComplexityPanel;

class ComplexityWorkflow : public Workflow {
    Q_OBJECT
public:
    explicit ComplexityWorkflow(Workbench &bench, QObject *parent = nullptr);
    ~ComplexityWorkflow() override;

    ComplexityController *controller() const { return m_controller; }
    // The last analysis shown, if any (cleared when another model is opened).
    const std::optional<ComplexityOutcome> &outcome() const { return m_outcome; }
    ComplexityPanel *panel() const { return m_panel; }
    CellHeatMap *heatMap() const { return m_heatMap.get(); }
    QAction *analyseAction() const { return m_analyse; }
    QAction *exportAction() const { return m_export; }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<Dock> docks() const override;
    WorkflowJob *job() const override;
    QAction *cancelAction() const override { return m_cancel; }
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;

public slots:
    // Opens the parameter dialog, then measures the complexity of the shown model.
    void analyse();
    // Measures with these parameters (one number of cells, no dialog); false when it cannot start.
    bool start(const ComplexityParams &params);
    void chooseCellsFile();
    // Writes the cells of the last analysis with their counts (.vtu); errors go to the messages.
    bool exportCells(const QString &path);
    void setHeatMapVisible(bool visible);
    void setHeatMapThreshold(int threshold);

private:
    void onStarted();
    void onMeasured(const ComplexityOutcome &outcome);
    void onFailed(const Message &error);
    void onCancelled();
    void updateHeatMapCount();

    ComplexityController *m_controller;
    std::optional<ComplexityOutcome> m_outcome;
    ComplexityParams m_lastParams;
    std::unique_ptr<CellHeatMap> m_heatMap;
    ComplexityPanel *m_panel;
    QDockWidget *m_dock;
    QAction *m_analyse;
    QAction *m_cancel;
    QAction *m_export;
    QAction *m_separator;
};

} // namespace stratamesh
