// What a test must know when the suite runs under AddressSanitizer + UndefinedBehaviorSanitizer
// (-DSTRATAMESH_SANITIZE=ON, scripts/sanitize.sh).
#pragma once

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

} // namespace stratamesh::test
