// Line-by-line tokenizer for Gocad ASCII files (formats.md §1.1): whitespace-separated tokens,
// double-quoted names with spaces, CRLF endings, '#' comment lines, and line numbers for errors.
#pragma once

#include "common/message_text.h"

#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace stratamesh {

class GocadLineTokenizer {
public:
    GocadLineTokenizer(std::istream &in, std::string fileName);

    // Moves to the next line that has at least one token (blank and '#' lines are skipped).
    // Returns false at the end of the input.
    bool next();
    // Makes the next call to next() return the current line again (one line of look-ahead).
    void pushBack();

    int lineNumber() const { return m_lineNumber; }
    // Number of the last line read, for errors found at the end of the input.
    int lastLineNumber() const { return m_physicalLine; }
    const std::string &fileName() const { return m_fileName; }
    // The current line without its end-of-line characters.
    const std::string &line() const { return m_line; }

    std::size_t size() const { return m_tokens.size(); }
    std::string_view token(std::size_t i) const { return m_tokens[i]; }
    // Case-insensitive comparison of token i (if present) with a keyword.
    bool is(std::size_t i, std::string_view keyword) const;
    // Tokens from i to the end joined by single spaces (unquoted names written with spaces).
    std::string joined(std::size_t from) const;

    // Token i as a number; throws FileError naming this line when missing or not a number.
    // `what` says what the token is, for the message ("x coordinate", "vertex id").
    double number(std::size_t i, std::string_view what) const;
    double finiteNumber(std::size_t i, std::string_view what) const;
    // A point coordinate: finite and within maxCoordinate (coordinate_bound.h).
    double coordinate(std::size_t i, std::string_view what) const;
    long long integer(std::size_t i, std::string_view what) const;
    // Throws unless the line has at least n tokens.
    void requireTokens(std::size_t n, std::string_view usage) const;

    [[noreturn]] void fail(const std::string &cause) const;
    [[noreturn]] void fail(const MessageText &cause) const;
    [[noreturn]] void failAt(int line, const std::string &cause) const;
    [[noreturn]] void failAt(int line, const MessageText &cause) const;

private:
    void tokenize();

    std::istream &m_in;
    std::string m_fileName;
    std::string m_line;
    std::string m_buffer; // unquoted token text; m_tokens point into it
    std::vector<std::string_view> m_tokens;
    int m_lineNumber = 0;
    int m_physicalLine = 0;
    bool m_pushedBack = false;
};

// Case-insensitive equality of ASCII words (Gocad type names vary in case: TSurf, TSURF).
bool gocadKeywordEquals(std::string_view a, std::string_view b);
// Parses a whole token as a number / integer; a leading '+' is accepted. False when invalid.
bool parseGocadNumber(std::string_view token, double &value);
bool parseGocadInteger(std::string_view token, long long &value);

} // namespace stratamesh
