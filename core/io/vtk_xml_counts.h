// The sizes an XML VTK file declares (NumberOfPoints, NumberOfCells, NumberOfTuples...), checked
// against the file's size before VTK's reader allocates them: VTK reserves what a header claims.
#pragma once

#include <string>

namespace stratamesh {

// Compressed data may expand up to about 1032 times (zlib's limit), so a count above that many
// values per byte of the file cannot be real. Throws FileError(path, line, cause) for such a count.
void checkVtkXmlCounts(const std::string &path);

} // namespace stratamesh
