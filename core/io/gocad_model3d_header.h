// Parser of the Gocad Model3d header object (formats.md §1.6): TSURF names, TFACE declarations
// with their key triangles, REGION / SURFACE / LAYER / FAULT_BLOCK id lists ended by 0.
#pragma once

#include "io/gocad_line_tokenizer.h"
#include "io/gocad_object_header.h"
#include "model/model.h"

#include <array>
#include <string>
#include <vector>

namespace stratamesh {

struct GocadHeaderTSurf {
    std::string name;
    int line = 0;
};

// "TFACE k type tsurf" and its three key-triangle lines.
struct GocadHeaderFace {
    long long id = 0;
    std::string type;
    std::string tsurf;
    bool hasKey = false;
    std::array<Vec3, 3> key; // z-up (negated when the header says ZPOSITIVE Depth)
    int line = 0;
};

// An id as listed in a REGION/SURFACE/LAYER block, with its sign and line for messages.
struct GocadListedId {
    long long id = 0; // signed for REGION sides
    int line = 0;
};

// "REGION id name", "SURFACE name", "LAYER name"... followed by ids up to 0.
struct GocadIdList {
    long long id = 0; // REGION id; 0 for the other lists
    std::string name;
    std::vector<GocadListedId> ids;
    int line = 0;
};

struct GocadModel3dHeader {
    GocadObjectInfo info;
    std::vector<GocadHeaderTSurf> tsurfs;
    std::vector<GocadHeaderFace> faces;
    std::vector<GocadIdList> regions; // first one is the Universe
    std::vector<GocadIdList> surfaceGroups;
    std::vector<GocadIdList> layers;
    int endLine = 0;
};

// Reads the Model3d object whose "GOCAD Model3d" line is current, up to and including its END.
GocadModel3dHeader parseGocadModel3dHeader(GocadLineTokenizer &tok, const GocadObjectInfo &info);

} // namespace stratamesh
