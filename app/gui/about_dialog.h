// Help > About: version, what the window offers, licence (AGPL-3.0-or-later) and the third-party
// note about TetGen. What it offers is the menus' own list, so About never claims a feature that
// no menu has (it once named hybrid meshes before any action made them).
#pragma once

#include <QString>
#include <QStringList>

class QWidget;

namespace stratamesh {

// `offered`: the texts of the actions that make or analyse something ("&Remesh…").
QString aboutText(const QStringList &offered);
void showAboutDialog(QWidget *parent, const QStringList &offered);

} // namespace stratamesh
