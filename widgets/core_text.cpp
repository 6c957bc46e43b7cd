#include "core_text.h"

#include <QCoreApplication>
#include <QStringList>

namespace stratamesh {

QString coreText(const MessageText &text, const std::string &english)
{
    if (text.pattern.empty())
        return QCoreApplication::translate(kCoreTextContext, english.c_str());
    const QString pattern = QCoreApplication::translate(kCoreTextContext, text.pattern.c_str());
    QStringList values;
    for (const std::string &arg : text.args)
        values << QString::fromStdString(arg);
    for (const MessageText &part : text.parts)
        values << coreText(part, part.text());
    // Filled in one pass, so a value holding "%2" is never filled again.
    QString out;
    out.reserve(pattern.size() + 16 * values.size());
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        const QChar c = pattern[i];
        const int n = i + 1 < pattern.size() ? pattern[i + 1].digitValue() : -1;
        if (c == QLatin1Char('%') && n >= 1 && n <= values.size()) {
            out += values[n - 1];
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace stratamesh
