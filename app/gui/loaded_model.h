// What the "open model" workflow hands to the window: the model with its topology, and what
// the user should read about it (validity problems, notes), or the error that stopped loading.
#pragma once

#include "message.h"
#include "model/model.h"
#include "model/model_counts.h"

#include <QMetaType>
#include <QString>

#include <memory>
#include <vector>

namespace stratamesh {

struct LoadedModel {
    QString path;        // empty for the bundled sample
    QString displayName; // file name, or "sample model"
    std::shared_ptr<const Model> model;
    ModelCounts counts; // thesis Table 3.1 counts, with and without the box
    std::vector<Message> messages;
    qint64 milliseconds = 0;
};

struct LoadResult {
    bool ok = false;
    bool cancelled = false; // stopped because the window closes
    LoadedModel loaded;     // when ok
    Message error;          // when not ok
};

} // namespace stratamesh

Q_DECLARE_METATYPE(stratamesh::LoadedModel)
