// The remesh section of the benchmark (issue 4): our remesh of modelA5 at 5000 sites (100 CVT
// iterations + mesh building) beside CGAL's isotropic_remeshing (Polygon Mesh Processing, each
// surface on its own, its border and contact edges protected or not) at the same target edge
// length: time, vertices, mean Q, % of triangles with an angle < 30°, Hausdorff distance, and
// whether the contacts stay conformal. Targets: ours ≤ 3 s on 2 cores, better quality than CGAL.
#pragma once

#include <string>

namespace stratamesh::bench {

// Reads modelA5.ml from dataDir; threads = 0 lets TBB choose; our remesh runs `repeat` times (the
// same model must come out each time). Returns 0, or 1 on error.
int runRemeshBench(const std::string &dataDir, int threads, int iterations, int repeat = 1);

} // namespace stratamesh::bench
