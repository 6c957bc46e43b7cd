// Sizes of the model elements (thesis §3.3.1): region volumes, surface areas, line lengths. They
// feed the size measure C_t and the variation coefficients of Table 3.3.
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh {

double surfaceArea(const Surface &surface);
double lineLength(const Model &model, const Line &line);

// Per element of the model, box included, in the model's order. Requires topology for lines.
struct ElementSizes {
    std::vector<double> regions;  // volumes (region sides, Gocad rule)
    std::vector<double> surfaces; // areas
    std::vector<double> lines;    // lengths
};
ElementSizes elementSizes(const Model &model);

} // namespace stratamesh
