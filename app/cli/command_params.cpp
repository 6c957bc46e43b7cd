#include "command_params.h"

#include "params/param_tables.h"
#include "params/param_text.h"

#include <cstring>

namespace stratamesh::cli {

std::vector<ParamInfo> commandParams(const Command &command)
{
    const std::string name = command.name;
    if (name == "remesh")
        return remeshParamTable().infos();
    if (name == "complexity")
        return complexityParamTable().infos();
    if (name == "tetmesh")
        return tetgenParamTable().infos();
    if (name == "cvt")
        return cvtParamTable().infos();
    if (name == "hybrid")
        return hybridParamTable().infos();
    return {};
}

std::string commandArguments(const Command &command)
{
    std::string arguments = command.arguments;
    const std::string placeholder = "{params}";
    const std::size_t at = arguments.find(placeholder);
    if (at == std::string::npos)
        return arguments;
    // The flags the line names itself, followed by a space, are left out of the generated list.
    const std::string named = arguments + ' ';
    arguments.replace(at, placeholder.size(), paramUsage(commandParams(command), named));
    return arguments;
}

std::string commandHelp(const Command &command)
{
    std::string text = "usage: stratamesh-cli " + std::string(command.name) + ' '
                       + commandArguments(command) + '\n' + command.summary + '\n';
    const std::vector<ParamInfo> params = commandParams(command);
    if (!params.empty())
        text += "\nparameters:\n" + paramHelp(params);
    return text;
}

std::string optionsMarkdown()
{
    std::string text;
    for (const Command &c : commands()) {
        const std::vector<ParamInfo> params = commandParams(c);
        if (params.empty())
            continue;
        if (!text.empty())
            text += '\n';
        text += "`" + std::string(c.name) + "`:\n\n" + paramMarkdown(params);
    }
    return text;
}

} // namespace stratamesh::cli
