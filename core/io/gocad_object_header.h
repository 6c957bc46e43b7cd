// Parts shared by every Gocad ASCII object (formats.md §1.1): the "GOCAD <Type> <version>" line,
// the HEADER { key:value } block (only `name` matters), the coordinate-system block with
// ZPOSITIVE, and the { } / BEGIN_…/END_… blocks that carry display or property metadata.
#pragma once

#include "io/gocad_line_tokenizer.h"

#include <string>

namespace stratamesh {

// What an object says about itself before its geometry.
struct GocadObjectInfo {
    std::string type;            // as written after GOCAD, e.g. "TSurf"
    std::string name;            // HEADER name, empty when absent
    bool zPositiveDepth = false; // ZPOSITIVE Depth: z grows downwards, negate to get z-up
    int firstLine = 0;           // line of "GOCAD <Type>"
};

// True when the current line is "GOCAD <Type> ..."; fills type and firstLine.
bool readGocadObjectLine(const GocadLineTokenizer &tok, GocadObjectInfo &info);

// Consumes the current line (and the rest of its block) when it is a HEADER, coordinate-system,
// ZPOSITIVE, { } block or atom-region-indicator block, updating info; returns false otherwise.
// Throws FileError when the file ends inside a block or ZPOSITIVE has an unknown value.
bool readGocadCommonLine(GocadLineTokenizer &tok, GocadObjectInfo &info);

// Skips an object of a type we do not read, up to and including its END line.
void skipGocadObject(GocadLineTokenizer &tok, const GocadObjectInfo &info);

// Throws FileError for a missing END: `tok` is on the next GOCAD line, or past the end of input
// when atEnd is true.
[[noreturn]] void failMissingGocadEnd(const GocadLineTokenizer &tok, const GocadObjectInfo &info,
                                      bool atEnd);

// "TSurf 'h1'" or "TSurf" for messages.
std::string describeGocadObject(const GocadObjectInfo &info);

} // namespace stratamesh
