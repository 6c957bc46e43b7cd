// What the window shows for an exception out of the core: a FileError names its own file and
// line; any other error is about `file` when given.
#pragma once

#include "message.h"

#include <exception>

namespace stratamesh {

Message errorMessage(const std::exception &e, const QString &file = QString());

} // namespace stratamesh
