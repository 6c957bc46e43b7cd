// Local complexity measures (thesis §3.3.2, §3.5.2, Table 3.4, Fig 3.7): a volumetric CVT of N
// sites in the model's axis-aligned bounding box, the number of elements each cell meets
// (cell_element_counts.h), and their statistics. The cells and per-cell counts are kept for
// heat maps and VTK export.
#pragma once

#include "common/progress.h"
#include "complexity/box_cvt.h"
#include "complexity/cell_element_counts.h"
#include "complexity/count_statistics.h"
#include "model/model.h"

#include <cstdint>
#include <vector>

namespace stratamesh {

struct LocalComplexityParams {
    int cells = 1000;
    std::uint64_t seed = 1;
    int iterations = 30; // Lloyd steps
};

struct LocalComplexity {
    BoxCvt cvt;                            // sites, cells (clipped polyhedra), energies
    std::vector<CellElementCounts> counts; // per cell
    // Statistics of the totals over the cells inside the model; cells meeting no element at all
    // (outside every region when the box is larger than the model) are left out and counted here.
    CountStatistics statistics;
    int outsideCells = 0;
    double cvtSeconds = 0.0;
    double countSeconds = 0.0;
};

// Requires topology; throws InputError otherwise or when cells < 1.
LocalComplexity localComplexity(const Model &model, const LocalComplexityParams &params,
                                Progress &progress = Progress::none());

} // namespace stratamesh
