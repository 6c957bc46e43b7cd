// What a test must know when the suite runs under AddressSanitizer + UndefinedBehaviorSanitizer
// (-DSTRATAMESH_SANITIZE=ON, scripts/sanitize.sh).
#pragma once

#include <initializer_list>
#include <vector>

namespace stratamesh::test {

#if defined(STRATAMESH_SANITIZED)
inline constexpr bool kSanitized = true;
// Instrumented code runs several times slower, unevenly (CGAL's templates most): the latency
// limits of the cancel and progress tests scale by this, so that what they still catch under the
// sanitizers is a stage that never ticks, not the instrumentation's cost.
inline constexpr double kTimeScale = 10.0;
#else
inline constexpr bool kSanitized = false;
inline constexpr double kTimeScale = 1.0;
#endif

// Under the sanitizers a data-matrix test (real models at several resolutions) runs its smallest
// case only, listed first: instrumented, the whole matrices took 100 of the suite's 107
// CPU-minutes, and the smallest case goes through the same code. The plain build runs every case.
inline std::vector<int> casesToRun(std::initializer_list<int> all)
{
    if (kSanitized && all.size() > 1)
        return {*all.begin()};
    return all;
}

// The skip message of a case that only the plain build runs.
inline constexpr const char *kPlainBuildOnly =
    "sanitized build: this data-matrix case runs in the plain build only (casesToRun)";

} // namespace stratamesh::test
