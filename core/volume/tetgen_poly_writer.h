// The PLC as a TetGen `.poly` file (formats.md §4.2; TetGen 1.5 manual §5.2.2), for running the
// `tetgen` executable on exactly what StrataMesh meshes and for reproducing a failure outside it.
#pragma once

#include "volume/plc.h"

#include <string>

namespace stratamesh {

// Points numbered from 1, one single-triangle polygon per facet with its marker, the holes, the
// region list (seed, attribute, no volume constraint). Written through atomic_file.h.
// Throws FileError when the file cannot be written.
void writeTetgenPoly(const Plc &plc, const std::string &path);

} // namespace stratamesh
