// One study task's input and output side by side, one camera, with the remesh ledger below;
// both models are read from the task folder (as the CLI wrote them), never recomputed.
#pragma once

#include "model/model.h"
#include "remesh/simplification_ledger.h"

#include <QWidget>

#include <memory>

namespace stratamesh {

class LedgerPanel;
class ModelScene;
class VtkViewWidget;

class TaskResultWindow : public QWidget {
    Q_OBJECT
public:
    explicit TaskResultWindow(QWidget *parent = nullptr);
    ~TaskResultWindow() override;

    // Output may be null (the task has no remesh, or it failed).
    void show(const QString &title, std::shared_ptr<const Model> input,
              std::shared_ptr<const Model> output, SimplificationLedger ledger);

    ModelScene *inputScene() const { return m_inputScene.get(); }
    ModelScene *outputScene() const { return m_outputScene.get(); }
    LedgerPanel *ledgerPanel() const { return m_ledger; }
    VtkViewWidget *inputView() const { return m_inputView; }
    VtkViewWidget *outputView() const { return m_outputView; }

private:
    VtkViewWidget *m_inputView;
    VtkViewWidget *m_outputView;
    std::unique_ptr<ModelScene> m_inputScene;
    std::unique_ptr<ModelScene> m_outputScene;
    LedgerPanel *m_ledger;
};

} // namespace stratamesh
