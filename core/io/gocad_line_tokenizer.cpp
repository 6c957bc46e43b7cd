#include "io/gocad_line_tokenizer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"

#include <charconv>
#include <cmath>

namespace stratamesh {

namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

char lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
}

std::string quoted(std::string_view s)
{
    return "'" + std::string(s) + "'";
}

// What the token is ("x coordinate"), marked for translation where the parsers name it.
MessageText whatText(std::string_view what)
{
    return {std::string(what)};
}

} // namespace

bool gocadKeywordEquals(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i]))
            return false;
    return true;
}

bool parseGocadNumber(std::string_view token, double &value)
{
    // from_chars is locale-independent and does not accept '+', which Gocad writers may emit.
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    if (token.empty())
        return false;
    const char *end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    return result.ec == std::errc() && result.ptr == end;
}

bool parseGocadInteger(std::string_view token, long long &value)
{
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    if (token.empty())
        return false;
    const char *end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    return result.ec == std::errc() && result.ptr == end;
}

GocadLineTokenizer::GocadLineTokenizer(std::istream &in, std::string fileName)
    : m_in(in), m_fileName(std::move(fileName))
{
}

bool GocadLineTokenizer::next()
{
    if (m_pushedBack) {
        m_pushedBack = false;
        return true;
    }
    while (std::getline(m_in, m_line)) {
        ++m_physicalLine;
        while (!m_line.empty() && (m_line.back() == '\r' || m_line.back() == '\n'))
            m_line.pop_back();
        std::size_t first = 0;
        while (first < m_line.size() && isSpace(m_line[first]))
            ++first;
        if (first == m_line.size() || m_line[first] == '#')
            continue;
        m_lineNumber = m_physicalLine;
        tokenize();
        return true;
    }
    m_tokens.clear();
    return false;
}

void GocadLineTokenizer::pushBack()
{
    m_pushedBack = true;
}

void GocadLineTokenizer::tokenize()
{
    // Quotes are removed while copying, so every token is a contiguous run of m_buffer; the
    // buffer is sized once per line so the views stay valid.
    m_tokens.clear();
    m_buffer.assign(m_line.size() + 1, '\0');
    std::size_t out = 0;
    std::size_t i = 0;
    const std::size_t n = m_line.size();
    while (i < n) {
        while (i < n && isSpace(m_line[i]))
            ++i;
        if (i == n)
            break;
        const std::size_t start = out;
        while (i < n && !isSpace(m_line[i])) {
            if (m_line[i] == '"') {
                // An unterminated quote runs to the end of the line: free text (HEADER values)
                // may hold a lone quote, and a name cut this way still fails where it is used.
                std::size_t close = m_line.find('"', i + 1);
                const bool terminated = close != std::string::npos;
                if (!terminated)
                    close = n;
                for (std::size_t k = i + 1; k < close; ++k)
                    m_buffer[out++] = m_line[k];
                i = terminated ? close + 1 : n;
            } else {
                m_buffer[out++] = m_line[i++];
            }
        }
        m_tokens.emplace_back(m_buffer.data() + start, out - start);
    }
}

bool GocadLineTokenizer::is(std::size_t i, std::string_view keyword) const
{
    return i < m_tokens.size() && gocadKeywordEquals(m_tokens[i], keyword);
}

std::string GocadLineTokenizer::joined(std::size_t from) const
{
    std::string s;
    for (std::size_t i = from; i < m_tokens.size(); ++i) {
        if (i > from)
            s += ' ';
        s += m_tokens[i];
    }
    return s;
}

double GocadLineTokenizer::number(std::size_t i, std::string_view what) const
{
    if (i >= m_tokens.size())
        fail(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "missing %1"), {}, {whatText(what)}});
    double v = 0.0;
    if (!parseGocadNumber(m_tokens[i], v))
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%2 %1 is not a number"),
                         {quoted(m_tokens[i])},
                         {whatText(what)}});
    return v;
}

double GocadLineTokenizer::finiteNumber(std::size_t i, std::string_view what) const
{
    const double v = number(i, what);
    if (!std::isfinite(v))
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%2 %1 is not finite"),
                         {quoted(m_tokens[i])},
                         {whatText(what)}});
    return v;
}

double GocadLineTokenizer::coordinate(std::size_t i, std::string_view what) const
{
    const double v = number(i, what);
    if (MessageText problem = coordinateProblem(v); !problem.pattern.empty())
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%2 %1 %3"),
                         {quoted(m_tokens[i])},
                         {whatText(what), std::move(problem)}});
    return v;
}

long long GocadLineTokenizer::integer(std::size_t i, std::string_view what) const
{
    if (i >= m_tokens.size())
        fail(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "missing %1"), {}, {whatText(what)}});
    long long v = 0;
    if (!parseGocadInteger(m_tokens[i], v))
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%2 %1 is not an integer"),
                         {quoted(m_tokens[i])},
                         {whatText(what)}});
    return v;
}

void GocadLineTokenizer::requireTokens(std::size_t n, std::string_view usage) const
{
    if (m_tokens.size() < n)
        fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "too few values, expected '%1'"),
                         {std::string(usage)}});
}

void GocadLineTokenizer::fail(const std::string &cause) const
{
    throw FileError(m_fileName, m_lineNumber, cause);
}

void GocadLineTokenizer::failAt(int line, const std::string &cause) const
{
    throw FileError(m_fileName, line, cause);
}

void GocadLineTokenizer::fail(const MessageText &cause) const
{
    throw FileError(m_fileName, m_lineNumber, cause);
}

void GocadLineTokenizer::failAt(int line, const MessageText &cause) const
{
    throw FileError(m_fileName, line, cause);
}

} // namespace stratamesh
