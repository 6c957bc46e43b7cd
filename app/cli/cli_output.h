// Where commands write: reports on stdout (JSON or text), diagnostics on stderr.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QTextStream>

namespace stratamesh::cli {

// Standard output as UTF-8 text; flushed by main before exit.
QTextStream &out();
// One indented JSON object on stdout, ending with a newline.
void printJson(const QJsonObject &object);
// "1234567" -> "1,234,567", for human-readable counts.
QString groupedNumber(qulonglong value);

} // namespace stratamesh::cli
