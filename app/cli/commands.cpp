#include "commands.h"

namespace stratamesh::cli {

const std::vector<Command> &commands()
{
#define STRATAMESH_CLI_ENTRY(name, function, arguments, summary)                                   \
    Command{name, function, arguments, summary},
    static const std::vector<Command> all = {STRATAMESH_CLI_COMMANDS(STRATAMESH_CLI_ENTRY)};
#undef STRATAMESH_CLI_ENTRY
    return all;
}

const Command *findCommand(const QString &name)
{
    for (const Command &c : commands()) {
        if (name == QLatin1String(c.name))
            return &c;
    }
    return nullptr;
}

} // namespace stratamesh::cli
