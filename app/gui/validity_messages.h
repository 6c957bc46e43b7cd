// Turns the core validity report into messages for the message panel.
#pragma once

#include "message.h"
#include "model/validity.h"

#include <vector>

namespace stratamesh {

std::vector<Message> validityMessages(const ValidityReport &report, const QString &file);

} // namespace stratamesh
