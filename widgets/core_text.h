// Core's sentences (ledger notes, validity problems) in the user's language: the pattern is
// translated in context kCoreTextContext and filled with core's values.
#pragma once

#include "common/message_text.h"

#include <QString>

namespace stratamesh {

// `english` is the text when there is no pattern (a ledger read back from a report): it is then
// looked up as a pattern without values, and shown as it is when the catalogue lacks it.
QString coreText(const MessageText &text, const std::string &english);

} // namespace stratamesh
