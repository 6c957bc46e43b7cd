// The hybrid section of the benchmark (issue 19): a hybrid tet/prism/pyramid mesh of modelA1 at
// 5000 sites, with the share of each stage (box CVT, surface remesh, thesis cells, TetGen fill,
// mixed-mesh check) and the cells per type. Target: under 20 s on 2 cores.
#pragma once

#include <string>

namespace stratamesh::bench {

// Reads modelA1.ml from dataDir; threads = 0 lets TBB choose; runs `repeat` times (the same mesh
// must come out each time). Returns 0, or 1 on error.
int runHybridBench(const std::string &dataDir, int threads, int repeat = 1);

} // namespace stratamesh::bench
