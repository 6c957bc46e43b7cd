// Reading Gocad ASCII structural models: a Model3d (.ml: header + one TSurf per TSURF) or plain
// TSurf files (.ts). Coordinates come out z-up (ZPOSITIVE Depth negated, formats.md §0 fact 1);
// topology is not built here (see model/topology.h).
#pragma once

#include "model/model.h"

#include <istream>
#include <string>

namespace stratamesh {

// Reads a Gocad file from a stream; fileName is only used in error messages and to name
// unnamed objects. The content decides: a leading Model3d object gives a model with regions,
// otherwise every TSurf object gives its surfaces (objects of other types are skipped).
// Throws FileError("file:line: cause") for any malformed or inconsistent input.
Model readGocad(std::istream &in, const std::string &fileName);

// Opens and reads a Gocad file; FileError when it cannot be opened.
Model readGocadFile(const std::string &path);

} // namespace stratamesh
