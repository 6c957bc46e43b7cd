// Gocad ASCII output of a surface model (formats.md §1.3, §1.6): TSurf (.ts) and Model3d (.ml).
//
// Surfaces are grouped into TSurf objects by Surface::sourceObject when their names are the
// ones a reader gives to the patches of that object ("obj" or "obj_1", "obj_2", ...) and they
// share feature name and type; any other surface gets a TSurf of its own named after it, so
// names survive a write-read round trip. Coordinates are written with the shortest text that
// reads back bit-exactly, z negated when the model is ZPOSITIVE Depth (the reader negates back;
// triangle order and region signs are kept, as the side rule is defined in the z-up frame).
#pragma once

#include "model/model.h"

#include <string>

namespace stratamesh {

// Model3d: TSURF/TFACE (key triangle = first triangle) / REGION / LAYER header, then one TSurf
// per TSURF. The Universe lists every surface side that no region claims, i.e. the signs
// opposite to the regions on the model boundary (unlike RINGMesh's writer, formats.md fact 3).
// With topology, BSTONE/BORDER give the corners and the start of every line of each face.
// Throws InputError for a model without surfaces or with an empty surface, FileError on write.
void writeGocadModel3d(const Model &model, const std::string &path);

// TSurf file: the surface with index `surface`, or every surface (several TSurf objects back to
// back) when surface < 0.
void writeGocadTSurf(const Model &model, const std::string &path, int surface = -1);

} // namespace stratamesh
