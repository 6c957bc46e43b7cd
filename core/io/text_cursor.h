// Line-by-line reading of a whole text file with line numbers for errors (CR LF tolerated); shared
// by the Gmsh and TSolid readers.
#pragma once

#include "common/error.h"

#include <string>
#include <string_view>
#include <vector>

namespace stratamesh {

class TextCursor {
public:
    // Reads the file; throws FileError(path, 0, "cannot open: <system cause>").
    explicit TextCursor(std::string path);

    // Moves to the next line; false at the end of the file.
    bool next();
    // Moves to the next line that is not blank; throws "unexpected end of file (expected WHAT)".
    void nextNonBlank(const char *expected);
    std::string_view line() const { return m_line; }
    int lineNumber() const { return m_lineNumber; }
    const std::string &path() const { return m_path; }
    // Whitespace-separated tokens of the current line.
    std::vector<std::string_view> tokens() const;

    [[noreturn]] void fail(const std::string &cause) const
    {
        throw FileError(m_path, m_lineNumber, cause);
    }
    [[noreturn]] void fail(const MessageText &cause) const
    {
        throw FileError(m_path, m_lineNumber, cause);
    }
    int toInt(std::string_view token, const char *what) const;
    double toDouble(std::string_view token, const char *what) const;
    // A count the file declares for what follows (nodes, elements): refused when negative or
    // when the rest of the file is too small to hold it, before anything is sized by it.
    int toCount(std::string_view token, const char *what, std::size_t minBytesPerItem) const;

private:
    std::string m_path;
    std::string m_text;
    std::size_t m_pos = 0;
    std::string_view m_line;
    int m_lineNumber = 0;
};

} // namespace stratamesh
