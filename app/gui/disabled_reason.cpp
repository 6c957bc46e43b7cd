#include "disabled_reason.h"

#include <QAction>
#include <QCoreApplication>
#include <QRegularExpression>

namespace stratamesh {

namespace {

const char *const kExplained = "stratamesh_disabled_reason";

void explain(QAction *action, const std::function<QString()> &reason)
{
    const QString why = action->isEnabled() ? QString() : reason();
    if (why.isEmpty()) {
        // Back to Qt's tooltip (the action's text); setToolTip() calls here again.
        if (action->property(kExplained).toBool()) {
            action->setProperty(kExplained, false);
            action->setToolTip(QString());
        }
        return;
    }
    QString text = action->text();
    text.remove(QRegularExpression(QStringLiteral("&(?!&)"))); // the mnemonic
    text.replace(QStringLiteral("&&"), QStringLiteral("&"));
    const QString tip = QCoreApplication::translate("DisabledReason", "%1: %2").arg(text, why);
    action->setProperty(kExplained, true);
    if (action->toolTip() != tip)
        action->setToolTip(tip);
}

} // namespace

void setDisabledReason(QAction *action, std::function<QString()> reason)
{
    // A second reason replaces the first: both would rewrite the tooltip after each other forever.
    QObject::disconnect(action, &QAction::changed, action, nullptr);
    QObject::connect(action, &QAction::changed, action,
                     [action, reason] { explain(action, reason); });
    explain(action, reason);
}

} // namespace stratamesh
