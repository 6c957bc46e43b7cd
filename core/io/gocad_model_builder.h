// Turns parsed Gocad objects into a Model (surfaces, regions, layers; no topology): one Surface
// per TFACE, named uniquely, typed from the Model3d header (formats.md §1.6, §0 fact 1).
#pragma once

#include "io/gocad_model3d_header.h"
#include "io/gocad_tsurf_parser.h"
#include "model/model.h"

#include <string>
#include <vector>

namespace stratamesh {

// A .ml file: the header and its body TSurfs. Surfaces follow the header TFACE order; region
// sides refer to them. Throws FileError for an inconsistent file (undeclared or missing TSurf,
// REGION naming an unknown TFACE, ...).
Model buildGocadModel3d(const GocadModel3dHeader &header, std::vector<GocadTSurf> bodies,
                        const std::string &fileName);

// A .ts file (or any file of TSurf objects): their surfaces, no regions.
Model buildGocadSurfaces(std::vector<GocadTSurf> tsurfs, const std::string &fileName);

// The file name without folders and extension, used to name unnamed objects.
std::string gocadFileStem(const std::string &fileName);

} // namespace stratamesh
