// One entry of the message panel: what happened, how bad, and where (file and line when known).
#pragma once

#include "model/model.h"

#include <QMetaType>
#include <QString>

#include <optional>

namespace stratamesh {

struct Message {
    enum class Severity { Info, Warning, Error };
    Severity severity = Severity::Info;
    QString text;
    QString file; // empty when the message is not about a file
    int line = 0; // 1-based; 0 when unknown
    // Where in the model (a validity problem): clicking the message flies the views there.
    std::optional<Vec3> position;
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::Message)
