// Saves a window, 3D view included, as a PNG image.
#pragma once

#include <QImage>
#include <QString>

class QWidget;

namespace stratamesh {

QImage grabWindow(QWidget *window);
// Writes through a temporary file and a rename; false when the image could not be written.
bool saveWindowScreenshot(QWidget *window, const QString &path);

} // namespace stratamesh
