// Pairs the TFACEs a Model3d header declares for one TSURF with the TFACEs of its body TSurf,
// using each header key triangle (formats.md §1.6): it is a triangle of the right face with the
// same vertex cycle in every real sample, though not always the first one.
#pragma once

#include "io/gocad_model3d_header.h"
#include "io/gocad_tsurf_parser.h"

#include <string>
#include <vector>

namespace stratamesh {

struct GocadFaceMatch {
    int bodyFace = -1;     // index in GocadTSurf::faces
    bool keyFound = false; // the key triangle is a triangle of that face
    bool reversed = false; // ...with the opposite vertex cycle: the face's sides are swapped
};

// One match per header face (same order). A face is matched to the body face holding its key
// triangle, preferring the same position; faces without a key or whose key is found nowhere
// fall back to position. Throws FileError (at the header TFACE line) when the counts differ, a
// key is ambiguous, or a face cannot be matched. Positions are compared exactly, in z-up.
std::vector<GocadFaceMatch> matchGocadFaces(const std::vector<const GocadHeaderFace *> &headerFaces,
                                            const GocadTSurf &body, const std::string &fileName);

} // namespace stratamesh
