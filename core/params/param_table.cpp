#include "params/param_table.h"

#include "common/error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace stratamesh {

std::string formatParamNumber(double value)
{
    char text[40];
    if (value == std::floor(value) && std::abs(value) < 1e15) {
        std::snprintf(text, sizeof text, "%.0f", value); // 10000000, not 1e+07
        return text;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(text, sizeof text, "%.*g", precision, value);
        if (std::strtod(text, nullptr) == value)
            break;
    }
    return text;
}

std::string paramRangeText(const ParamInfo &info)
{
    std::string text =
        "[" + formatParamNumber(info.minimum) + ", " + formatParamNumber(info.maximum) + "]";
    if (info.zeroMeansOff && info.minimum > 0.0)
        text += " or 0";
    if (!info.unit.empty())
        text += " " + info.unit;
    return text;
}

std::string paramValueError(const ParamInfo &info, double value)
{
    if (info.type == ParamType::Flag)
        return {};
    const bool whole = info.type != ParamType::Real;
    if (std::isfinite(value) && (!whole || value == std::floor(value))
        && ((value >= info.minimum && value <= info.maximum)
            || (info.zeroMeansOff && value == 0.0)))
        return {};
    return "is " + formatParamNumber(value) + ", outside " + paramRangeText(info);
}

void throwParamError(const std::string &algorithm, const ParamInfo &info, const std::string &why)
{
    throw InputError(algorithm + ": " + info.key + " " + why + " (" + info.flag + ")");
}

} // namespace stratamesh
