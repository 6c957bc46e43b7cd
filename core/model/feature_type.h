// Geological type of a surface, as Gocad's TFACE types map onto it (formats.md §1.6, §3.2).
#pragma once

#include <string>
#include <string_view>

namespace stratamesh {

enum class FeatureType { Horizon, Fault, Unconformity, Boundary, Unknown };

// "top", "none", "topographic" → Horizon; "*fault" → Fault; "boundary", "lease" → Boundary.
FeatureType featureTypeFromGocad(std::string_view gocadType);
// The word written back to Gocad files ("top", "fault", "unconformity", "boundary", "none").
std::string gocadTypeName(FeatureType type);
// Lower-case English name for reports and JSON ("horizon", "fault", ...).
std::string featureTypeName(FeatureType type);

} // namespace stratamesh
