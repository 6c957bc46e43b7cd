// Texts made from a parameter table: the usage line, the CLI help and the README's Markdown.
#pragma once

#include "params/param_table.h"

#include <string>
#include <vector>

namespace stratamesh {

// "[--d-resolution D] [--iterations N] [--adaptive]", leaving out the flags in `skip` (those a
// command's usage line already names, as "(--sites N | --edge-length L)").
std::string paramUsage(const std::vector<ParamInfo> &params, const std::string &skip = {});

// One block per parameter: "  --sites N" then the help, range, default, unit and thesis
// reference, indented.
std::string paramHelp(const std::vector<ParamInfo> &params);

// A Markdown table: option, meaning, default, range, thesis.
std::string paramMarkdown(const std::vector<ParamInfo> &params);

// The default as a form or a table shows it: "0.4", "off", "on".
std::string paramDefaultText(const ParamInfo &info);

} // namespace stratamesh
