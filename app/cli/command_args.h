// The arguments of one stratamesh-cli command, read in a fixed order: flags and options first,
// then positionals, then finish() rejects whatever was not read, so a typo is never ignored.
#pragma once

#include "params/param_table.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace stratamesh::cli {

// Bad command line: main prints it with the command's usage and exits with status 2.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const QString &message) : std::runtime_error(message.toStdString()) {}
};

class CommandArgs {
public:
    CommandArgs(QString command, QStringList arguments);

    const QString &command() const { return m_command; }

    // "--json": true when present.
    bool flag(const QString &name);
    // "--sites 5000" or "--sites=5000"; UsageError when the value is missing.
    std::optional<QString> option(const QString &name);
    // Numeric options with a range check; UsageError names the option and the accepted range.
    int intOption(const QString &name, int defaultValue, int minimum, int maximum);
    double doubleOption(const QString &name, double defaultValue, double minimum, double maximum);

    // The next positional argument; UsageError "missing WHAT" when there is none.
    QString positional(const QString &what);
    std::optional<QString> optionalPositional();

    // UsageError for any argument not read: unknown options and extra positionals.
    void finish() const;

    // The value of one table parameter given on the command line, if it is: 1 for a flag,
    // the number (or the numbers of a list) of an option. UsageError "--sites expects an
    // integer in [4, 10000000] or 0, got '2'" for a value its entry does not accept.
    std::optional<std::vector<double>> paramValue(const ParamInfo &info);

    // Sets every parameter of `table` given on the command line and returns their keys.
    template <class P>
    std::vector<std::string> params(const ParamTable<P> &table, P &params)
    {
        std::vector<std::string> given;
        for (const Param<P> &p : table.params()) {
            const std::optional<std::vector<double>> value = paramValue(p.info);
            if (!value)
                continue;
            if (p.info.type == ParamType::IntList)
                p.setList(params, *value);
            else
                p.set(params, value->front());
            given.push_back(p.info.key);
        }
        return given;
    }

private:
    struct Token {
        QString text;
        bool used = false;
        bool afterSeparator = false; // after "--": never an option
    };
    std::vector<Token> m_tokens;
    QString m_command;
};

} // namespace stratamesh::cli
