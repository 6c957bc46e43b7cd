#include "io/file_bytes.h"

#include "common/error.h"
#include "common/translate_noop.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace stratamesh {

std::string readFileBytes(const std::string &path)
{
    std::FILE *f = std::fopen(path.c_str(), "rb");
    if (!f)
        throw FileError(path, 0,
                        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open: %1"),
                                    {std::strerror(errno)}});
    std::string bytes;
    char buffer[1 << 16];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0)
        bytes.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed)
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot read the file"));
    return bytes;
}

} // namespace stratamesh
