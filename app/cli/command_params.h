// The parameter table behind each command (core/params), for its usage line, its --help and the
// README's option list (stratamesh-cli help --markdown).
#pragma once

#include "commands.h"
#include "params/param_table.h"

#include <string>
#include <vector>

namespace stratamesh::cli {

// The parameters of the table a command reads; empty when it has none.
std::vector<ParamInfo> commandParams(const Command &command);

// The command's arguments with "{params}" replaced by its table's options (those the line does
// not already name).
std::string commandArguments(const Command &command);

// "usage: ..." then the summary and one block per table parameter.
std::string commandHelp(const Command &command);

// The option lists of every command with a table, as Markdown (the README's "Options" section).
std::string optionsMarkdown();

} // namespace stratamesh::cli
