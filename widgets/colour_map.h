// Perceptual colour maps for measures drawn on surfaces: viridis (van der Walt & Smith, matplotlib
// 2015) from a few control points, oriented so that the bad end of a measure is always the warm
// (yellow) end, whichever way the measure grows.
#pragma once

#include <vtkSmartPointer.h>

class vtkLookupTable;

namespace stratamesh {

// 256 colours over [low, high]. `lowIsBad`: low values (min angle, Q) take the warm end; else
// high values (a distance) do. `reverse` swaps the ends for the user who prefers it.
vtkSmartPointer<vtkLookupTable> measureLookupTable(double low, double high, bool lowIsBad,
                                                   bool reverse = false);

} // namespace stratamesh
