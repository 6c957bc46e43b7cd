// Help > About: version, licence (AGPL-3.0-or-later) and the third-party note about TetGen.
#pragma once

class QWidget;

namespace stratamesh {

void showAboutDialog(QWidget *parent);

} // namespace stratamesh
