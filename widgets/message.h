// One entry of the message panel: what happened, how bad, and where (file and line when known).
#pragma once

#include <QMetaType>
#include <QString>

namespace stratamesh {

struct Message {
    enum class Severity { Info, Warning, Error };
    Severity severity = Severity::Info;
    QString text;
    QString file; // empty when the message is not about a file
    int line = 0; // 1-based; 0 when unknown
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::Message)
