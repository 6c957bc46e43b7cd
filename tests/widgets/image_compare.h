// Pixel counting helpers for rendering tests.
#pragma once

#include <QColor>
#include <QImage>

#include <cstdlib>

namespace stratamesh::test {

// Pixels whose colour differs by more than `tolerance` (any channel) between two same-size images.
inline int differingPixels(const QImage &a, const QImage &b, int tolerance = 12)
{
    if (a.size() != b.size())
        return -1;
    const QImage x = a.convertToFormat(QImage::Format_RGB32),
                 y = b.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            if (std::abs(qRed(p[col]) - qRed(q[col])) > tolerance
                || std::abs(qGreen(p[col]) - qGreen(q[col])) > tolerance
                || std::abs(qBlue(p[col]) - qBlue(q[col])) > tolerance)
                ++n;
    }
    return n;
}

// Pixels with a clearly saturated colour (the grey-blue background and grey UI are not).
inline int saturatedPixels(const QImage &image, int minSaturation = 90)
{
    const QImage x = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        for (int col = 0; col < x.width(); ++col)
            if (QColor::fromRgb(p[col]).hsvSaturation() >= minSaturation)
                ++n;
    }
    return n;
}

} // namespace stratamesh::test
