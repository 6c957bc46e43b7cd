// Where the user's choices outlive the window (recent files, the window's layout): the settings of
// organisation and application "StrataMesh", or, when STRATAMESH_SETTINGS_DIR names a folder, an
// INI file there. A program other than the application (a test) that names no folder gets fresh
// settings in a temporary folder: a test never reads nor writes the developer's settings.
#pragma once

#include <memory>

class QSettings;

namespace stratamesh {

std::unique_ptr<QSettings> openSettings();

} // namespace stratamesh
