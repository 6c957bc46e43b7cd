#include "io/text_cursor.h"

#include "common/translate_noop.h"
#include "io/file_bytes.h"
#include "io/number_text.h"

#include <limits>

namespace stratamesh {

TextCursor::TextCursor(std::string path) : m_path(std::move(path)), m_text(readFileBytes(m_path)) {}

bool TextCursor::next()
{
    if (m_pos >= m_text.size())
        return false;
    std::size_t end = m_text.find('\n', m_pos);
    if (end == std::string::npos)
        end = m_text.size();
    m_line = std::string_view(m_text).substr(m_pos, end - m_pos);
    if (!m_line.empty() && m_line.back() == '\r')
        m_line.remove_suffix(1);
    m_pos = end + 1;
    ++m_lineNumber;
    return true;
}

void TextCursor::nextNonBlank(const char *expected)
{
    while (next())
        if (m_line.find_first_not_of(" \t") != std::string_view::npos)
            return;
    ++m_lineNumber;
    fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "unexpected end of file (expected %1)"),
                     {expected}});
}

std::vector<std::string_view> TextCursor::tokens() const
{
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < m_line.size()) {
        while (i < m_line.size() && (m_line[i] == ' ' || m_line[i] == '\t'))
            ++i;
        std::size_t j = i;
        while (j < m_line.size() && m_line[j] != ' ' && m_line[j] != '\t')
            ++j;
        if (j > i)
            out.push_back(m_line.substr(i, j - i));
        i = j;
    }
    return out;
}

int TextCursor::toInt(std::string_view token, const char *what) const
{
    long long v = 0;
    if (!parseInt(token, v) || v < std::numeric_limits<int>::min()
        || v > std::numeric_limits<int>::max())
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "expected %1, found \"%2\""),
                         {what, std::string(token)}});
    return static_cast<int>(v);
}

int TextCursor::toCount(std::string_view token, const char *what, std::size_t minBytesPerItem) const
{
    const int n = toInt(token, what);
    if (n < 0)
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 is negative (%2)"),
                         {std::string(what), std::to_string(n)}});
    const std::size_t remaining = m_pos < m_text.size() ? m_text.size() - m_pos : 0;
    if (static_cast<std::size_t>(n) > remaining / minBytesPerItem)
        fail(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core",
                              "%1 is %2, more than the remaining %3 bytes of the file can hold"),
            {std::string(what), std::to_string(n), std::to_string(remaining)}});
    return n;
}

double TextCursor::toDouble(std::string_view token, const char *what) const
{
    double v = 0;
    if (!parseDouble(token, v))
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "expected %1, found \"%2\""),
                         {what, std::string(token)}});
    return v;
}

} // namespace stratamesh
