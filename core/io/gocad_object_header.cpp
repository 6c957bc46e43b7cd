#include "io/gocad_object_header.h"
#include "common/translate_noop.h"

#include <string_view>

namespace stratamesh {

namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

bool startsWithNoCase(std::string_view s, std::string_view prefix)
{
    return s.size() >= prefix.size() && gocadKeywordEquals(s.substr(0, prefix.size()), prefix);
}

// "HEADER {", "HEADER{name:x", "HEADER: {" and "HEADER" followed by a "{" line all open it.
bool isHeaderLine(const GocadLineTokenizer &tok)
{
    const std::string_view t = tok.token(0);
    if (!startsWithNoCase(t, "HEADER"))
        return false;
    const std::string_view rest = t.substr(6);
    return rest.empty() || rest.front() == '{' || rest.front() == ':';
}

// One "key:value" entry of a HEADER block; keeps the first `name`.
void readHeaderEntry(std::string_view entry, GocadObjectInfo &info)
{
    const std::size_t colon = entry.find(':');
    if (colon == std::string_view::npos || !info.name.empty())
        return;
    if (!gocadKeywordEquals(trim(entry.substr(0, colon)), "name"))
        return;
    std::string_view value = trim(entry.substr(colon + 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
    info.name = std::string(value);
}

// A block left open would swallow the END of its object, or the next object, and merge them.
void refuseEndInBlock(const GocadLineTokenizer &tok, const char *block, int start)
{
    if (tok.is(0, "END") || tok.is(0, "GOCAD"))
        tok.fail(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "%1 started at line %2 is not closed by '}' before %3"),
                        {std::string(block), std::to_string(start), std::string(tok.token(0))}});
}

void readHeaderBlock(GocadLineTokenizer &tok, GocadObjectInfo &info)
{
    const int start = tok.lineNumber();
    std::string_view text = tok.line();
    std::size_t open = text.find('{');
    while (open == std::string_view::npos) {
        if (!tok.next())
            tok.failAt(tok.lastLineNumber(),
                       MessageText{QT_TRANSLATE_NOOP(
                                       "stratamesh::Core",
                                       "file ends inside the HEADER block started at line %1"),
                                   {std::to_string(start)}});
        refuseEndInBlock(tok, "the HEADER block", start);
        text = tok.line();
        open = text.find('{');
    }
    text = text.substr(open + 1);
    for (;;) {
        const std::size_t close = text.find('}');
        readHeaderEntry(text.substr(0, close), info);
        if (close != std::string_view::npos)
            return;
        if (!tok.next())
            tok.failAt(tok.lastLineNumber(),
                       MessageText{QT_TRANSLATE_NOOP(
                                       "stratamesh::Core",
                                       "file ends inside the HEADER block started at line %1"),
                                   {std::to_string(start)}});
        refuseEndInBlock(tok, "the HEADER block", start);
        text = tok.line();
    }
}

void readZPositive(const GocadLineTokenizer &tok, GocadObjectInfo &info)
{
    if (tok.is(1, "Depth"))
        info.zPositiveDepth = true;
    else if (tok.is(1, "Elevation"))
        info.zPositiveDepth = false;
    else
        tok.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "ZPOSITIVE must be Elevation or Depth"));
}

void readCoordinateSystem(GocadLineTokenizer &tok, GocadObjectInfo &info)
{
    const int start = tok.lineNumber();
    while (tok.next()) {
        if (tok.is(0, "END_ORIGINAL_COORDINATE_SYSTEM"))
            return;
        if (tok.is(0, "ZPOSITIVE"))
            readZPositive(tok, info);
        else if (tok.is(0, "END") || tok.is(0, "GOCAD"))
            tok.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                   "coordinate system block started at line %1 "
                                                   "has no END_ORIGINAL_COORDINATE_SYSTEM"),
                                 {std::to_string(start)}});
    }
    tok.failAt(tok.lastLineNumber(),
               MessageText{QT_TRANSLATE_NOOP(
                               "stratamesh::Core",
                               "file ends inside the coordinate system block started at line %1"),
                           {std::to_string(start)}});
}

// PROPERTY_CLASS_HEADER X { … } and similar display blocks: skipped up to the closing brace.
void skipBraceBlock(GocadLineTokenizer &tok)
{
    const int start = tok.lineNumber();
    std::string_view text = tok.line();
    text = text.substr(text.find('{') + 1);
    while (text.find('}') == std::string_view::npos) {
        if (!tok.next())
            tok.failAt(
                tok.lastLineNumber(),
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "file ends inside the { } block started at line %1"),
                            {std::to_string(start)}});
        refuseEndInBlock(tok, "the { } block", start);
        text = tok.line();
    }
}

void skipUntil(GocadLineTokenizer &tok, std::string_view endKeyword)
{
    const int start = tok.lineNumber();
    while (tok.next())
        if (tok.is(0, endKeyword))
            return;
    tok.failAt(
        tok.lastLineNumber(),
        MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "file ends before %1 closing the block started at line %2"),
                    {std::string(endKeyword), std::to_string(start)}});
}

} // namespace

bool readGocadObjectLine(const GocadLineTokenizer &tok, GocadObjectInfo &info)
{
    if (!tok.is(0, "GOCAD"))
        return false;
    if (tok.size() < 2)
        tok.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "GOCAD line without an object type"));
    info = GocadObjectInfo();
    info.type = std::string(tok.token(1));
    info.firstLine = tok.lineNumber();
    return true;
}

bool readGocadCommonLine(GocadLineTokenizer &tok, GocadObjectInfo &info)
{
    if (isHeaderLine(tok)) {
        readHeaderBlock(tok, info);
        return true;
    }
    if (tok.is(0, "GOCAD_ORIGINAL_COORDINATE_SYSTEM")) {
        readCoordinateSystem(tok, info);
        return true;
    }
    if (tok.is(0, "ZPOSITIVE")) {
        readZPositive(tok, info);
        return true;
    }
    if (tok.is(0, "BEGIN_ATOM_REGION_INDICATORS")) {
        skipUntil(tok, "END_ATOM_REGION_INDICATORS");
        return true;
    }
    const std::string &line = tok.line();
    const std::size_t open = line.find('{');
    if (open != std::string::npos && line.find('}', open) == std::string::npos) {
        skipBraceBlock(tok);
        return true;
    }
    return false;
}

void skipGocadObject(GocadLineTokenizer &tok, const GocadObjectInfo &info)
{
    // Blocks are consumed so that an END inside them cannot end the object early.
    GocadObjectInfo scratch = info;
    while (tok.next()) {
        if (tok.is(0, "END"))
            return;
        if (tok.is(0, "GOCAD"))
            failMissingGocadEnd(tok, info, false);
        readGocadCommonLine(tok, scratch);
    }
    failMissingGocadEnd(tok, info, true);
}

void failMissingGocadEnd(const GocadLineTokenizer &tok, const GocadObjectInfo &info, bool atEnd)
{
    const std::string what =
        describeGocadObject(info) + " started at line " + std::to_string(info.firstLine);
    if (atEnd)
        tok.failAt(
            tok.lastLineNumber(),
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "file ends before the END of %1 (truncated file?)"),
                        {what}});
    tok.fail(MessageText{
        QT_TRANSLATE_NOOP("stratamesh::Core", "missing END of %1 before the next GOCAD object"),
        {what}});
}

std::string describeGocadObject(const GocadObjectInfo &info)
{
    return info.name.empty() ? info.type : info.type + " '" + info.name + "'";
}

} // namespace stratamesh
