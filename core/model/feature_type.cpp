#include "model/feature_type.h"

#include <algorithm>
#include <cctype>

namespace stratamesh {

FeatureType featureTypeFromGocad(std::string_view gocadType)
{
    std::string t(gocadType);
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
    if (t == "top" || t == "none" || t == "topographic" || t == "horizon" || t == "intrusive")
        return FeatureType::Horizon;
    if (t.find("fault") != std::string::npos)
        return FeatureType::Fault;
    if (t == "unconformity")
        return FeatureType::Unconformity;
    if (t == "boundary" || t == "lease" || t == "voi")
        return FeatureType::Boundary;
    return FeatureType::Unknown;
}

std::string gocadTypeName(FeatureType type)
{
    switch (type) {
    case FeatureType::Horizon:
        return "top";
    case FeatureType::Fault:
        return "fault";
    case FeatureType::Unconformity:
        return "unconformity";
    case FeatureType::Boundary:
        return "boundary";
    case FeatureType::Unknown:
        break;
    }
    return "none";
}

std::string featureTypeName(FeatureType type)
{
    switch (type) {
    case FeatureType::Horizon:
        return "horizon";
    case FeatureType::Fault:
        return "fault";
    case FeatureType::Unconformity:
        return "unconformity";
    case FeatureType::Boundary:
        return "boundary";
    case FeatureType::Unknown:
        break;
    }
    return "unknown";
}

} // namespace stratamesh
