#include "exaggeration_workflow.h"

#include "workbench.h"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QLocale>
#include <QMainWindow>
#include <QMenu>
#include <QUndoCommand>
#include <QUndoStack>

#include <algorithm>

namespace stratamesh {

namespace {

class ExaggerationCommand : public QUndoCommand {
public:
    ExaggerationCommand(ExaggerationWorkflow &workflow, double before, double after,
                        const QString &text)
        : QUndoCommand(text), m_workflow(workflow), m_before(before), m_after(after)
    {
    }
    void undo() override { m_workflow.applyExaggeration(m_before); }
    void redo() override { m_workflow.applyExaggeration(m_after); }

private:
    ExaggerationWorkflow &m_workflow;
    double m_before;
    double m_after;
};

QString factorText(double factor)
{
    // "2×", "0.5×", "12.5×" in the user's locale.
    return QLocale().toString(factor, 'g', 4) + QStringLiteral("×");
}

} // namespace

ExaggerationWorkflow::ExaggerationWorkflow(Workbench &bench, QObject *parent)
    : Workflow(bench, parent), m_menu(new QMenu(bench.window())), m_group(new QActionGroup(this)),
      m_custom(new QAction(this))
{
    m_menu->setObjectName(QStringLiteral("VerticalExaggerationMenu"));
    for (std::size_t i = 0; i < kPresets.size(); ++i) {
        m_presets[i] = new QAction(this);
        m_presets[i]->setCheckable(true);
        m_group->addAction(m_presets[i]);
        m_menu->addAction(m_presets[i]);
        connect(m_presets[i], &QAction::triggered, this,
                [this, i] { chooseExaggeration(kPresets[i]); });
    }
    m_menu->addSeparator();
    m_custom->setCheckable(true);
    m_group->addAction(m_custom);
    m_menu->addAction(m_custom);
    connect(m_custom, &QAction::triggered, this, &ExaggerationWorkflow::askCustom);
    // A project or an undo may have changed it since the menu was last open.
    connect(m_menu, &QMenu::aboutToShow, this, &ExaggerationWorkflow::syncChecks);
    syncChecks();
}

QList<QAction *> ExaggerationWorkflow::menuActions(Menu menu) const
{
    if (menu != Menu::View)
        return {};
    return {m_menu->menuAction()};
}

void ExaggerationWorkflow::retranslate()
{
    m_menu->setTitle(tr("Vertical E&xaggeration"));
    m_menu->menuAction()->setStatusTip(
        tr("Stretch the vertical axis of both views, to see thin layers and low dips"));
    for (std::size_t i = 0; i < kPresets.size(); ++i)
        m_presets[i]->setText(i == 0 ? tr("%1 (true scale)").arg(factorText(kPresets[i]))
                                     : factorText(kPresets[i]));
    syncChecks();
}

void ExaggerationWorkflow::clear()
{
    // Another model: true scale again, and nothing to undo (the undo stack is cleared too).
    applyExaggeration(1.0);
}

double ExaggerationWorkflow::exaggeration() const
{
    return m_bench.verticalExaggeration();
}

void ExaggerationWorkflow::chooseExaggeration(double factor)
{
    factor = std::clamp(factor, kMinimum, kMaximum);
    const double before = exaggeration();
    if (factor == before) {
        syncChecks();
        return;
    }
    m_bench.undoStack()->push(new ExaggerationCommand(
        *this, before, factor, tr("Vertical exaggeration %1").arg(factorText(factor))));
}

void ExaggerationWorkflow::applyExaggeration(double factor)
{
    const double before = exaggeration();
    m_bench.setVerticalExaggeration(factor);
    syncChecks();
    if (exaggeration() != before)
        m_bench.setStatus(factor == 1.0 ? tr("Vertical exaggeration off: true scale")
                                        : tr("Vertical exaggeration %1: the views are not to scale")
                                              .arg(factorText(factor)));
}

void ExaggerationWorkflow::askCustom()
{
    bool ok = false;
    const double factor = QInputDialog::getDouble(
        m_bench.window(), tr("Vertical Exaggeration"),
        tr("Vertical axis stretched by (%1 to %2):")
            .arg(QLocale().toString(kMinimum), QLocale().toString(kMaximum)),
        exaggeration(), kMinimum, kMaximum, 1, &ok);
    if (ok)
        chooseExaggeration(factor);
    else
        syncChecks();
}

void ExaggerationWorkflow::syncChecks()
{
    const double factor = exaggeration();
    const auto preset = std::find(kPresets.begin(), kPresets.end(), factor);
    const bool isPreset = preset != kPresets.end();
    for (std::size_t i = 0; i < kPresets.size(); ++i)
        m_presets[i]->setChecked(isPreset && kPresets[i] == factor);
    m_custom->setChecked(!isPreset);
    m_custom->setText(isPreset ? tr("&Other…") : tr("&Other (%1)…").arg(factorText(factor)));
}

} // namespace stratamesh
