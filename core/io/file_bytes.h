// The whole content of a file, for the parsers that read from memory (text and legacy VTK).
#pragma once

#include <string>

namespace stratamesh {

// Throws FileError naming the file when it cannot be opened or read.
std::string readFileBytes(const std::string &path);

} // namespace stratamesh
