#include "core_text.h"

#include <QCoreApplication>

namespace stratamesh {

QString coreText(const MessageText &text, const std::string &english)
{
    if (text.pattern.empty())
        return QCoreApplication::translate(kCoreTextContext, english.c_str());
    const QString pattern = QCoreApplication::translate(kCoreTextContext, text.pattern.c_str());
    // Filled in one pass, so a value holding "%2" is never filled again.
    QString out;
    out.reserve(pattern.size() + 16 * int(text.args.size()));
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        const QChar c = pattern[i];
        const int n = i + 1 < pattern.size() ? pattern[i + 1].digitValue() : -1;
        if (c == QLatin1Char('%') && n >= 1 && std::size_t(n) <= text.args.size()) {
            out += QString::fromStdString(text.args[std::size_t(n - 1)]);
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace stratamesh
