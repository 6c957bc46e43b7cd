// The bytes of a legacy .vtk file, read the way VTK's legacy reader reads them:
// whitespace-separated tokens (newlines included), whole lines (the header, ASCII strings) and raw
// bytes (BINARY data), each with the line it starts on, counted as an editor counts them (every
// '\n', binary or not).
#pragma once

#include "common/message_text.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace stratamesh {

class VtkLegacyCursor {
public:
    // Reads the whole file; throws FileError(path, 0, cause) when it cannot.
    explicit VtkLegacyCursor(std::string path);

    const std::string &path() const { return m_path; }
    std::size_t fileSize() const { return m_text.size(); }
    // Bytes after the position: what any count the file declares from here must fit in.
    std::size_t remaining() const { return m_text.size() - m_pos; }

    // The next token, past any whitespace; empty at the end of the file.
    std::string_view token();
    // The token token() would return, without moving.
    std::string_view peekToken() const;
    // Line of the last token returned (of the last line or bytes read after it).
    int tokenLine() const { return m_tokenLine; }

    // The rest of the current line without its '\n' (and a '\r' before it); moves past the '\n'.
    // False at the end of the file.
    bool line(std::string_view &text);
    // Moves past the end of the current line, which must hold nothing but whitespace after the
    // last token: throws "<what> is followed by '...' on its line" otherwise.
    void endLine(const std::string &what);
    // True when only whitespace is left before the end of the current line.
    bool restOfLineBlank() const;

    // The next `n` bytes as they are (BINARY data); the caller checked that they are there.
    std::string_view bytes(std::size_t n);

    [[noreturn]] void fail(int line, const std::string &cause) const;
    [[noreturn]] void fail(int line, const MessageText &cause) const;

private:
    void moveTo(std::size_t pos);

    std::string m_path;
    std::string m_text;
    std::size_t m_pos = 0;
    int m_line = 1; // line of m_pos
    int m_tokenLine = 1;
};

// Bytes of a token fit for a message: at most 40, anything outside printable ASCII as '?'.
std::string vtkPrintable(std::string_view text);

// Whether `token` is `keyword` in any case ("cell_data" is CELL_DATA, as VTK takes it).
bool vtkKeywordIs(std::string_view token, std::string_view keyword);

} // namespace stratamesh
