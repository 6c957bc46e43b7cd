// View > Vertical Exaggeration: z stretched in both views (1×, 2×, 5×, 10×, 20× or any factor
// from 0.1 to 50), so that thin layers, small throws and low dips can be seen. Each choice is
// undoable; a project keeps it with its view; another model starts at true scale.
#pragma once

#include "workflow.h"

#include <array>

class QActionGroup;
class QMenu;

namespace stratamesh {

class ExaggerationWorkflow : public Workflow {
    Q_OBJECT
public:
    static constexpr double kMinimum = 0.1;
    static constexpr double kMaximum = 50.0;
    static constexpr std::array<double, 5> kPresets{1.0, 2.0, 5.0, 10.0, 20.0};

    explicit ExaggerationWorkflow(Workbench &bench, QObject *parent = nullptr);

    QList<QAction *> menuActions(Menu menu) const override;
    void retranslate() override;
    void clear() override;

    // As the user does: an undoable command, unless nothing changes; `factor` is clamped to
    // [kMinimum, kMaximum].
    void chooseExaggeration(double factor);
    // The command's work: both views, the status line and the menu's check mark.
    void applyExaggeration(double factor);
    double exaggeration() const;
    QAction *presetAction(std::size_t index) const { return m_presets[index]; }
    QAction *customAction() const { return m_custom; }
    QMenu *menu() const { return m_menu; }

private:
    void askCustom();
    void syncChecks();

    QMenu *m_menu;
    QActionGroup *m_group;
    std::array<QAction *, kPresets.size()> m_presets{};
    QAction *m_custom;
};

} // namespace stratamesh
