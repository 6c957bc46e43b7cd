// stratamesh-cli: thin batch front end over the core library; each command is one file
// (commands.h lists them). Exit status: 0 success, 1 error (input, processing), 2 bad usage.
#include "cli_output.h"
#include "command_params.h"
#include "commands.h"
#include "common/error.h"
#include "common/version.h"

#include <QCoreApplication>

#include <exception>
#include <iostream>
#include <new>

using namespace stratamesh;
using namespace stratamesh::cli;

namespace {

void printHelp(std::ostream &stream)
{
    stream << "stratamesh-cli " << STRATAMESH_VERSION
           << " - remeshing and meshing of 3D structural models\n\n"
              "usage: stratamesh-cli COMMAND [ARGUMENTS]\n"
              "       stratamesh-cli COMMAND --help\n"
              "       stratamesh-cli help --markdown   (option lists as Markdown)\n"
              "       stratamesh-cli --version | --help\n\n"
              "commands:\n";
    for (const Command &c : commands()) {
        stream << "  " << c.name << ' ' << commandArguments(c) << "\n      " << c.summary << '\n';
    }
    stream << "\nExit status: 0 success, 1 error (the message names the file and line), "
              "2 bad usage.\n";
}

void printCommandUsage(std::ostream &stream, const Command &c)
{
    stream << "usage: stratamesh-cli " << c.name << ' ' << commandArguments(c) << '\n';
}

int fail(const std::string &message)
{
    out().flush();
    std::cerr << "stratamesh-cli: error: " << message << std::endl;
    return 1;
}

int runCommand(const Command &command, const QStringList &arguments)
{
    try {
        CommandArgs args(QString::fromLatin1(command.name), arguments);
        const int status = command.run(args);
        out().flush();
        return status;
    } catch (const UsageError &e) {
        out().flush();
        std::cerr << "stratamesh-cli " << command.name << ": " << e.what() << '\n';
        printCommandUsage(std::cerr, command);
        return 2;
    } catch (const FileError &e) {
        return fail(e.what());
    } catch (const InputError &e) {
        return fail(e.what());
    } catch (const Cancelled &e) {
        return fail(e.what());
    } catch (const std::bad_alloc &) {
        return fail("out of memory");
    } catch (const std::exception &e) {
        return fail(e.what());
    } catch (...) {
        return fail("unknown error");
    }
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stratamesh-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STRATAMESH_VERSION));
    QStringList arguments = QCoreApplication::arguments().mid(1);

    if (arguments.isEmpty()) {
        printHelp(std::cerr);
        return 2;
    }
    const QString first = arguments.takeFirst();
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        std::cout << "stratamesh-cli " << STRATAMESH_VERSION << '\n';
        return 0;
    }
    if (first == QLatin1String("--help") || first == QLatin1String("-h")
        || first == QLatin1String("help")) {
        if (!arguments.isEmpty()) {
            if (arguments.first() == QLatin1String("--markdown")) {
                std::cout << optionsMarkdown();
                return 0;
            }
            if (const Command *c = findCommand(arguments.first())) {
                std::cout << commandHelp(*c);
                return 0;
            }
            std::cerr << "stratamesh-cli: unknown command '" << arguments.first().toStdString()
                      << "'\n";
            return 2;
        }
        printHelp(std::cout);
        return 0;
    }
    const Command *command = findCommand(first);
    if (!command) {
        std::cerr << "stratamesh-cli: unknown command '" << first.toStdString()
                  << "' (try stratamesh-cli --help)\n";
        return 2;
    }
    if (arguments.contains(QLatin1String("--help")) || arguments.contains(QLatin1String("-h"))) {
        std::cout << commandHelp(*command);
        return 0;
    }
    return runCommand(*command, arguments);
}
