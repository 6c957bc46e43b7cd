// Pieces shared by the Gocad writers (TSurf, Model3d, TSolid): names, coordinate system, vertices.
#pragma once

#include "model/model.h"

#include <ostream>
#include <string>

namespace stratamesh {

// A name as one Gocad token: double-quoted when it holds blanks (formats.md §1.1), never empty.
std::string gocadToken(const std::string &name);

// GOCAD_ORIGINAL_COORDINATE_SYSTEM block; ZPOSITIVE Depth when the model came that way.
void writeGocadCoordinateSystem(std::ostream &out, bool zPositiveDepth);

// "HEADER {" / "name: ..." / "}".
void writeGocadHeader(std::ostream &out, const std::string &name);

// "x y z" in file coordinates (z negated for Depth), shortest text that reads back bit-exactly.
void writeGocadPoint(std::ostream &out, const Vec3 &p, bool zPositiveDepth);

} // namespace stratamesh
