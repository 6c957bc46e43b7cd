// Third global measure of the thesis (§3.3.1, Table 3.3): the variation coefficient of the sizes
// of the elements of each type, box elements excluded — sample standard deviation over mean of
// the region volumes, of the surface areas and of the line lengths. (The thesis footnote says
// "mean over standard deviation"; its numbers are std/mean.)
#pragma once

#include "model/model.h"

namespace stratamesh {

struct SizeVariation {
    double regions = 0.0;
    double surfaces = 0.0;
    double lines = 0.0; // 0 when fewer than two inner lines (Table 3.3 leaves it blank)
    double total = 0.0; // the sum of the three, as the thesis's "Total" row
};

// Requires topology; throws InputError otherwise.
SizeVariation sizeVariation(const Model &model);

} // namespace stratamesh
