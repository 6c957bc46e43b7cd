#include "feature_palette.h"

#include <array>

namespace stratamesh {

namespace {

// Muted, print-friendly hues in the spirit of geological map conventions.
constexpr std::array<QRgb, 8> kHorizon{0x8cbf5f, 0xe2c15a, 0xc98f52, 0x63ad90,
                                       0xd6d07a, 0xa97c55, 0x9fcf8a, 0xe8a663};
constexpr std::array<QRgb, 6> kFault{0xd1453b, 0xe2743b, 0xb63a6e, 0xe05d5d, 0xa9322a, 0xd98a6c};
constexpr std::array<QRgb, 5> kUnconformity{0x4c7fca, 0x7b63c4, 0x3aa0c8, 0x5a5fb0, 0x6fb3e0};
constexpr std::array<QRgb, 4> kUnknown{0x8c9aa8, 0x9c8fa6, 0x7fa5a1, 0xa6a08c};
constexpr QRgb kBoundary = 0xb8c2cc;

template <std::size_t N>
QColor pick(const std::array<QRgb, N> &palette, int index)
{
    return QColor::fromRgb(palette[std::size_t(index < 0 ? 0 : index) % N]);
}

} // namespace

QColor featureTypeColor(FeatureType type)
{
    return featureColor(type, 0, 0);
}

QColor featureColor(FeatureType type, int featureIndex, int surfaceIndex)
{
    QColor base;
    switch (type) {
    case FeatureType::Horizon:
        base = pick(kHorizon, featureIndex);
        break;
    case FeatureType::Fault:
        base = pick(kFault, featureIndex);
        break;
    case FeatureType::Unconformity:
        base = pick(kUnconformity, featureIndex);
        break;
    case FeatureType::Boundary:
        base = QColor::fromRgb(kBoundary);
        break;
    case FeatureType::Unknown:
        base = pick(kUnknown, featureIndex);
        break;
    }
    // Alternate lighter/darker steps: 0, +1, -1, +2, -2 ... limited to keep the hue readable.
    if (surfaceIndex <= 0)
        return base;
    const int step = (surfaceIndex + 1) / 2 % 4;
    const int factor = 100 + 9 * (step == 0 ? 1 : step);
    return (surfaceIndex % 2 == 1) ? base.lighter(factor) : base.darker(factor);
}

QColor contactLineColor()
{
    return QColor::fromRgb(0x1f2328);
}
QColor boxLineColor()
{
    return QColor::fromRgb(0x5d6873);
}
QColor cornerColor()
{
    return QColor::fromRgb(0xffd84d);
}

} // namespace stratamesh
