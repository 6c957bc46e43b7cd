#!/usr/bin/env bash
# Builds StrataMesh with AddressSanitizer + UndefinedBehaviorSanitizer (-DSTRATAMESH_SANITIZE=ON)
# in build-sanitize/ and runs the whole CTest suite under them, GUI tests in a virtual X server.
# Any sanitizer report fails its test. Leaks inside Debian's libraries (Qt, Mesa, fontconfig, VTK)
# are suppressed entry by entry in scripts/lsan-suppressions.txt; leaks in our code are not.
# Usage: scripts/sanitize.sh [ctest options...]   e.g. scripts/sanitize.sh -L unit
#   SANITIZE_BUILD=dir   another build folder
#   SANITIZE_CMAKE_ARGS  more cmake options, e.g. "-DSTRATAMESH_BUILD_GUI=OFF" to leave out the GUI
#                        (a third of the build) when time is short
#   SANITIZE_EXCLUDE     a ctest -E regex of tests left out
#   SANITIZE_GUI_DEADLINE  a time (seconds since 1970) after which the GUI tests are not started
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SANITIZE_BUILD:-$root/build-sanitize}"
jobs="$(nproc 2>/dev/null || echo 2)"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-5G}"
# -g1 would otherwise put the build folder in every hash: another clone would miss the cache.
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

start=$(date +%s)
# -O1: the sanitizers' usual trade between build time, run time and readable stacks.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DSTRATAMESH_SANITIZE=ON ${SANITIZE_CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j "$jobs"
built=$(date +%s)
echo "sanitize: built in $((built - start)) s"

# allocator_may_return_null: a refused huge allocation is std::bad_alloc, as in a normal build,
# which the readers' out-of-memory paths and their tests rely on.
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:detect_stack_use_after_return=0:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exclude=()
if [[ -n "${SANITIZE_EXCLUDE:-}" ]]; then
    exclude=(-E "$SANITIZE_EXCLUDE")
    left=$(ctest --test-dir "$build" -N -R "$SANITIZE_EXCLUDE" | grep -c 'Test *#' || true)
    echo "sanitize: leaving out $left test(s) matching '$SANITIZE_EXCLUDE'"
fi
status=0
xvfb-run -a -s "-screen 0 1600x1000x24" \
    ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE "lint|gui" "${exclude[@]}" "$@" \
    || status=$?
if [[ -n "${SANITIZE_GUI_DEADLINE:-}" ]] && (($(date +%s) > SANITIZE_GUI_DEADLINE)); then
    echo "sanitize: GUI tests left out: past SANITIZE_GUI_DEADLINE"
    echo "sanitize: tests ran in $(($(date +%s) - built)) s"
    exit "$status"
fi
# The GUI tests without leak checks: Mesa's drivers and libdbus are loaded with dlopen and gone
# by the time LeakSanitizer looks, so their one-time allocations have no module to suppress by
# (1.3 KB in 4-10 blocks per GUI test). Memory errors and undefined behaviour still fail them.
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" xvfb-run -a -s "-screen 0 1600x1000x24" \
    ctest --test-dir "$build" --output-on-failure -j "$jobs" -L gui "${exclude[@]}" "$@" || status=$?
end=$(date +%s)
echo "sanitize: tests ran in $((end - built)) s"
exit "$status"
