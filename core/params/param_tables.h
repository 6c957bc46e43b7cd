// The parameter table of each algorithm the front ends expose (param_table.h says what an entry
// holds). The structs themselves stay beside their algorithms, with their defaults.
#pragma once

#include "complexity/complexity_report.h"
#include "cvt/cvt_optimizer.h"
#include "hybrid/hybrid_mesher.h"
#include "params/param_table.h"
#include "remesh/surface_remesher.h"
#include "volume/tetgen_runner.h"

namespace stratamesh {

// sites, edge_length, d_resolution, strip_factor, iterations, seed, refinement_rounds, adaptive,
// merge_all (thesis ch. 4).
const ParamTable<RemeshParams> &remeshParamTable();
// h, alpha, cells, seed, iterations (thesis ch. 3).
const ParamTable<ComplexityParams> &complexityParamTable();
// quality, max_volume, time_limit, memory_limit, refine_surfaces, no_merge (thesis §5.2).
const ParamTable<TetgenParams> &tetgenParamTable();
// iterations, alpha, lloyd (thesis §4.3).
const ParamTable<CvtParams> &cvtParamTable();
// sites, thin_ratio, vertex_min_dihedral, iterations, surface_iterations, seed, max_warp,
// pyramid_height, quality (thesis ch. 5).
const ParamTable<HybridParams> &hybridParamTable();

} // namespace stratamesh
