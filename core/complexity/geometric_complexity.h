// Second global measure of the thesis (§3.3.1, Table 3.2): the geometric complexity of each
// element, C_t + C_f + C_e + C_a, each in [0, 1], relative to a characteristic size h and an
// angle α, summed per element type. Box elements are left out (their own complexity is not
// counted), though they bound the regions whose thickness and angles are measured.
//
// - C_t (size): 1 when size(e) <= h^d (d = 3 regions, 2 surfaces, 1 lines), else 0.
// - C_f (shape): shape_measure.h. 0 for regions.
// - C_e (thickness): region_thickness.h (regions), surface_width.h (surfaces); 0 for lines.
// - C_a (angles): angle_measure.h (regions, surfaces); 0 for lines.
// Pellerin et al. 2015, "Elements for measuring the complexity of 3D structural models:
// connectivity and geometry", Computers & Geosciences 76.
#pragma once

#include "common/progress.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct GeometricParams {
    double h = 100.0;           // characteristic size, model units (m)
    double alphaDegrees = 20.0; // angle threshold
};

struct ElementMeasures {
    int element = -1;       // index in Model::regions / surfaces / lines
    double size = 0.0;      // C_t
    double shape = 0.0;     // C_f
    double thickness = 0.0; // C_e
    double angle = 0.0;     // C_a
    double sum() const { return size + shape + thickness + angle; }
};

struct GeometricComplexity {
    std::vector<ElementMeasures> regions;
    std::vector<ElementMeasures> surfaces; // inner surfaces only
    std::vector<ElementMeasures> lines;    // inner lines only
    double regionsTotal = 0.0;
    double surfacesTotal = 0.0;
    double linesTotal = 0.0;
    double total() const { return regionsTotal + surfacesTotal + linesTotal; }
};

// Requires topology. Throws InputError when h <= 0 or alpha is not in (0, 180].
GeometricComplexity geometricComplexity(const Model &model, const GeometricParams &params,
                                        Progress &progress = Progress::none());

} // namespace stratamesh
