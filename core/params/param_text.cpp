#include "params/param_text.h"

#include <sstream>

namespace stratamesh {

namespace {

std::string withoutShortcut(const std::string &label)
{
    std::string text;
    for (std::size_t i = 0; i < label.size(); ++i) {
        if (label[i] == '&' && i + 1 < label.size() && label[i + 1] != '&')
            continue;
        text += label[i];
    }
    while (!text.empty() && (text.back() == ':' || text.back() == ' '))
        text.pop_back();
    return text;
}

std::string optionText(const ParamInfo &p)
{
    return p.type == ParamType::Flag ? p.flag : p.flag + " " + p.valueName;
}

} // namespace

std::string paramDefaultText(const ParamInfo &info)
{
    if (info.type == ParamType::Flag)
        return info.defaultValue != 0.0 ? "on" : "off";
    if (info.type == ParamType::IntList) {
        std::string text;
        for (double v : info.defaultList)
            text += (text.empty() ? "" : ",") + formatParamNumber(v);
        return text;
    }
    return formatParamNumber(info.defaultValue);
}

std::string paramUsage(const std::vector<ParamInfo> &params, const std::string &skip)
{
    std::string usage;
    for (const ParamInfo &p : params) {
        if (!skip.empty() && skip.find(p.flag + " ") != std::string::npos)
            continue;
        if (!usage.empty())
            usage += ' ';
        usage += "[" + optionText(p) + "]";
    }
    return usage;
}

std::string paramHelp(const std::vector<ParamInfo> &params)
{
    std::ostringstream s;
    for (const ParamInfo &p : params) {
        s << "  " << optionText(p) << "\n      " << p.help;
        if (p.type != ParamType::Flag) {
            s << " Range " << paramRangeText(p);
            s << ", default " << paramDefaultText(p);
            s << '.';
        }
        if (!p.thesis.empty())
            s << " Thesis " << p.thesis << '.';
        s << '\n';
    }
    return s.str();
}

std::string paramMarkdown(const std::vector<ParamInfo> &params)
{
    std::ostringstream s;
    s << "| option | meaning | default | range | thesis |\n"
      << "|---|---|---|---|---|\n";
    for (const ParamInfo &p : params) {
        s << "| `" << optionText(p) << "` | " << withoutShortcut(p.label) << ": " << p.help << " | "
          << paramDefaultText(p) << " | "
          << (p.type == ParamType::Flag ? std::string() : paramRangeText(p)) << " | " << p.thesis
          << " |\n";
    }
    return s.str();
}

} // namespace stratamesh
