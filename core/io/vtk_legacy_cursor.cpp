#include "io/vtk_legacy_cursor.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/file_bytes.h"

#include <algorithm>

namespace stratamesh {

namespace {

// What C++ streams skip between tokens in the classic locale, as VTK's reader does.
bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

} // namespace

VtkLegacyCursor::VtkLegacyCursor(std::string path)
    : m_path(std::move(path)), m_text(readFileBytes(m_path))
{
}

void VtkLegacyCursor::moveTo(std::size_t pos)
{
    m_line += static_cast<int>(std::count(m_text.begin() + static_cast<std::ptrdiff_t>(m_pos),
                                          m_text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    m_pos = pos;
}

std::string_view VtkLegacyCursor::token()
{
    std::size_t start = m_pos;
    while (start < m_text.size() && isSpace(m_text[start]))
        ++start;
    moveTo(start);
    m_tokenLine = m_line;
    std::size_t end = start;
    while (end < m_text.size() && !isSpace(m_text[end]))
        ++end;
    m_pos = end; // no '\n' inside a token
    return std::string_view(m_text).substr(start, end - start);
}

std::string_view VtkLegacyCursor::peekToken() const
{
    std::size_t start = m_pos;
    while (start < m_text.size() && isSpace(m_text[start]))
        ++start;
    std::size_t end = start;
    while (end < m_text.size() && !isSpace(m_text[end]))
        ++end;
    return std::string_view(m_text).substr(start, end - start);
}

bool VtkLegacyCursor::line(std::string_view &text)
{
    if (m_pos >= m_text.size())
        return false;
    m_tokenLine = m_line;
    std::size_t end = m_text.find('\n', m_pos);
    if (end == std::string::npos)
        end = m_text.size();
    text = std::string_view(m_text).substr(m_pos, end - m_pos);
    if (!text.empty() && text.back() == '\r')
        text.remove_suffix(1);
    moveTo(std::min(end + 1, m_text.size()));
    return true;
}

bool VtkLegacyCursor::restOfLineBlank() const
{
    for (std::size_t i = m_pos; i < m_text.size() && m_text[i] != '\n'; ++i)
        if (!isSpace(m_text[i]))
            return false;
    return true;
}

void VtkLegacyCursor::endLine(const std::string &what)
{
    if (!restOfLineBlank()) {
        std::size_t start = m_pos;
        while (isSpace(m_text[start]))
            ++start;
        std::size_t end = start;
        while (end < m_text.size() && !isSpace(m_text[end]))
            ++end;
        fail(
            m_line,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 is followed by '%2' on its line"),
                        {what, vtkPrintable(std::string_view(m_text).substr(start, end - start))}});
    }
    const std::size_t end = m_text.find('\n', m_pos);
    moveTo(end == std::string::npos ? m_text.size() : end + 1);
}

std::string_view VtkLegacyCursor::bytes(std::size_t n)
{
    const std::size_t start = m_pos;
    moveTo(start + n);
    return std::string_view(m_text).substr(start, n);
}

void VtkLegacyCursor::fail(int line, const std::string &cause) const
{
    throw FileError(m_path, line, cause);
}

void VtkLegacyCursor::fail(int line, const MessageText &cause) const
{
    throw FileError(m_path, line, cause);
}

std::string vtkPrintable(std::string_view text)
{
    std::string out(text.substr(0, 40));
    for (char &c : out)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
            c = '?';
    return out;
}

bool vtkKeywordIs(std::string_view token, std::string_view keyword)
{
    if (token.size() != keyword.size())
        return false;
    for (std::size_t i = 0; i < token.size(); ++i) {
        const char c = token[i];
        const char upper = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
        if (upper != keyword[i])
            return false;
    }
    return true;
}

} // namespace stratamesh
