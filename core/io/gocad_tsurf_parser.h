// Parser of one Gocad TSurf object (formats.md §1.2, §1.3): TFACE patches with VRTX/PVRTX/ATOM/
// PATOM vertices and TRGL triangles, then BSTONE/BORDER. Vertex ids are mapped through a hash,
// never by position, and each TFACE gets its own local, 0-based vertices.
#pragma once

#include "io/gocad_line_tokenizer.h"
#include "io/gocad_object_header.h"
#include "model/model.h"

#include <string>
#include <vector>

namespace stratamesh {

// One TFACE: vertices (z-up) referenced by its triangles, in file order; triangle order kept.
struct GocadFace {
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
    int line = 0; // line of the TFACE keyword (or of the first record when TFACE is omitted)
};

// BORDER id corner next: a boundary line of a face starts at BSTONE `corner` and goes to `next`.
struct GocadBorder {
    long long id = 0; // opaque (a hand-written sample reuses vertex ids)
    long long corner = 0;
    long long next = 0;
    int line = 0;
};

struct GocadTSurf {
    GocadObjectInfo info;
    std::string geologicalFeature; // GEOLOGICAL_FEATURE, empty when absent
    std::string geologicalType;    // GEOLOGICAL_TYPE, empty when absent
    std::vector<GocadFace> faces;
    std::vector<long long> borderStones; // BSTONE vertex ids (validated)
    std::vector<GocadBorder> borders;    // validated: both vertex ids exist
    int endLine = 0;
};

// Reads the object whose "GOCAD TSurf" line is current (already read into `info`) up to and
// including its END. Throws FileError naming the line for every malformed record.
GocadTSurf parseGocadTSurf(GocadLineTokenizer &tok, const GocadObjectInfo &info);

} // namespace stratamesh
