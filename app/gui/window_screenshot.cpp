#include "window_screenshot.h"

#include <QImageWriter>
#include <QSaveFile>
#include <QWidget>

namespace stratamesh {

QImage grabWindow(QWidget *window)
{
    // Qt 6 renders QOpenGLWidget children into QWidget::grab() through their framebuffers.
    return window->grab().toImage();
}

bool saveWindowScreenshot(QWidget *window, const QString &path)
{
    const QImage image = grabWindow(window);
    if (image.isNull())
        return false;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    QImageWriter writer(&file, "png");
    if (!writer.write(image)) {
        file.cancelWriting();
        return false;
    }
    return file.commit();
}

} // namespace stratamesh
