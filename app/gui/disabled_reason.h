// A disabled action says why in its tooltip ("Save Remeshed Model As…: no remeshed model yet"), so
// that a greyed menu entry or tool button is not a riddle. The reason is asked each time the action
// changes (enabled, text retranslated), so it may depend on the state and be translated.
#pragma once

#include <QString>

#include <functional>

class QAction;

namespace stratamesh {

// A later call for the same action replaces its reason.
void setDisabledReason(QAction *action, std::function<QString()> reason);

} // namespace stratamesh
