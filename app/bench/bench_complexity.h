// The complexity section of the benchmark (issue 5): thesis Tables 3.2, 3.3 and 3.4 on the real
// models A1, A2, A5 printed beside the thesis's values, and the time of the local measures at
// 10,000 cells on modelA5 (target: 20 s on 2 cores).
#pragma once

#include <string>

namespace stratamesh::bench {

// Reads modelA1/A2/A5.ml from dataDir; threads = 0 lets TBB choose. Returns 0, or 1 on error.
int runComplexityBench(const std::string &dataDir, int threads);

} // namespace stratamesh::bench
