#include "command_args.h"

namespace stratamesh::cli {

namespace {

bool looksLikeOption(const QString &text)
{
    if (!text.startsWith(QLatin1Char('-')) || text.size() < 2)
        return false;
    bool isNumber = false;
    text.toDouble(&isNumber); // "-5" is a value, not an option
    return !isNumber;
}

} // namespace

CommandArgs::CommandArgs(QString command, QStringList arguments) : m_command(std::move(command))
{
    bool separator = false;
    for (QString &a : arguments) {
        if (!separator && a == QLatin1String("--")) {
            separator = true;
            continue;
        }
        m_tokens.push_back({std::move(a), false, separator});
    }
}

bool CommandArgs::flag(const QString &name)
{
    bool found = false;
    for (Token &t : m_tokens) {
        if (!t.used && !t.afterSeparator && t.text == name) {
            t.used = true;
            found = true;
        }
    }
    return found;
}

std::optional<QString> CommandArgs::option(const QString &name)
{
    std::optional<QString> value;
    const QString prefix = name + QLatin1Char('=');
    for (std::size_t i = 0; i < m_tokens.size(); ++i) {
        Token &t = m_tokens[i];
        if (t.used || t.afterSeparator)
            continue;
        if (t.text.startsWith(prefix)) {
            t.used = true;
            value = t.text.mid(prefix.size());
        } else if (t.text == name) {
            t.used = true;
            if (i + 1 >= m_tokens.size() || m_tokens[i + 1].used)
                throw UsageError(QStringLiteral("option %1 needs a value").arg(name));
            m_tokens[i + 1].used = true;
            value = m_tokens[i + 1].text;
        }
    }
    return value;
}

int CommandArgs::intOption(const QString &name, int defaultValue, int minimum, int maximum)
{
    const std::optional<QString> text = option(name);
    if (!text)
        return defaultValue;
    bool ok = false;
    const int value = text->toInt(&ok);
    if (!ok || value < minimum || value > maximum)
        throw UsageError(QStringLiteral("%1 expects an integer in [%2, %3], got '%4'")
                             .arg(name)
                             .arg(minimum)
                             .arg(maximum)
                             .arg(*text));
    return value;
}

double CommandArgs::doubleOption(const QString &name, double defaultValue, double minimum,
                                 double maximum)
{
    const std::optional<QString> text = option(name);
    if (!text)
        return defaultValue;
    bool ok = false;
    const double value = text->toDouble(&ok);
    if (!ok || !(value >= minimum && value <= maximum))
        throw UsageError(QStringLiteral("%1 expects a number in [%2, %3], got '%4'")
                             .arg(name)
                             .arg(minimum)
                             .arg(maximum)
                             .arg(*text));
    return value;
}

std::optional<std::vector<double>> CommandArgs::paramValue(const ParamInfo &info)
{
    const QString name = QString::fromStdString(info.flag);
    if (info.type == ParamType::Flag) {
        if (!flag(name))
            return std::nullopt;
        return std::vector<double>{1.0};
    }
    const std::optional<QString> text = option(name);
    if (!text)
        return std::nullopt;
    const bool whole = info.type != ParamType::Real;
    const QString expects = info.type == ParamType::IntList ? QStringLiteral("integers")
                            : whole                         ? QStringLiteral("an integer")
                                                            : QStringLiteral("a number");
    auto refuse = [&]() {
        return UsageError(
            QStringLiteral("%1 expects %2 in %3, got '%4'")
                .arg(name, expects,
                     QString::fromStdString(paramRangeText(info))
                         + (info.type == ParamType::IntList ? QStringLiteral(" separated by commas")
                                                            : QString()),
                     *text));
    };
    const QStringList parts =
        info.type == ParamType::IntList ? text->split(QLatin1Char(',')) : QStringList{*text};
    std::vector<double> values;
    for (const QString &part : parts) {
        bool ok = false;
        // Whole numbers as integers, so that "1e3" or "2.5" is not a number of sites.
        const double value = whole ? static_cast<double>(part.trimmed().toLongLong(&ok))
                                   : part.trimmed().toDouble(&ok);
        if (!ok || !paramValueError(info, value).empty())
            throw refuse();
        values.push_back(value);
    }
    return values;
}

std::optional<QString> CommandArgs::optionalPositional()
{
    for (Token &t : m_tokens) {
        if (t.used)
            continue;
        if (!t.afterSeparator && looksLikeOption(t.text))
            continue; // left for finish() to report as unknown
        t.used = true;
        return t.text;
    }
    return std::nullopt;
}

QString CommandArgs::positional(const QString &what)
{
    const std::optional<QString> value = optionalPositional();
    if (!value)
        throw UsageError(QStringLiteral("missing %1").arg(what));
    return *value;
}

void CommandArgs::finish() const
{
    for (const Token &t : m_tokens) {
        if (t.used)
            continue;
        if (!t.afterSeparator && looksLikeOption(t.text))
            throw UsageError(QStringLiteral("unknown option %1").arg(t.text));
        throw UsageError(QStringLiteral("unexpected argument '%1'").arg(t.text));
    }
}

} // namespace stratamesh::cli
