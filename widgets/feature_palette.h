// Colours of surfaces by geological feature type: one family of hues per type (horizons in
// greens and ochres, faults in reds, unconformities in blues), one colour per feature, and a
// small shade step per surface so the patches of one feature stay related but distinguishable.
#pragma once

#include "model/feature_type.h"

#include <QColor>

namespace stratamesh {

// The representative colour of a type (legend swatch).
QColor featureTypeColor(FeatureType type);
// featureIndex counts features of the same type; surfaceIndex counts surfaces of the feature.
QColor featureColor(FeatureType type, int featureIndex, int surfaceIndex);
QColor contactLineColor();
QColor boxLineColor();
QColor cornerColor();

} // namespace stratamesh
