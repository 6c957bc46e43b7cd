// The file stratamesh-tetgen (app/tetgen_runner) writes and core/volume/tetgen_runner.cpp reads, in
// the machine's byte order (both run on the same host): a header, then points as 3 doubles, tets as
// 4 zero-based point ids and the region attribute (int32 each), boundary faces as 3 ids and the
// facet marker.
#pragma once

#include <cstdint>

namespace stratamesh::tetgen_result {

// Starts the helper's own messages on stderr; anything else in the log is TetGen's (or the C
// library's, as "stratamesh-tetgen: file:line: ...: Assertion `...' failed.").
inline constexpr const char *kHelperPrefix = "[stratamesh-tetgen] ";

struct Header {
    char magic[8] = {'S', 'M', 'T', 'E', 'T', 'S', '1', '\n'};
    std::int64_t points = 0;
    std::int64_t tets = 0;
    std::int64_t faces = 0;
};

} // namespace stratamesh::tetgen_result
