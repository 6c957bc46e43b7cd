#!/usr/bin/env bash
# Builds the libFuzzer harnesses of the readers with clang (ASan + UBSan) in build-fuzz/ and runs
# each for a bounded time under CTest (label fuzz), seeded with tests/fuzz/seeds, the committed
# hostile inputs of tests/fuzz/regressions (each also run once as a regression test) and the real
# models of ../shared/data; then prints how many inputs each fuzzer ran.
# Usage: scripts/fuzz.sh [SECONDS_EACH]   (default 15; FUZZ_BUILD=dir for another build folder;
#        FUZZ_SEED=N for a fixed libFuzzer seed, as CI does; unset: random)
# A finding fails the run and is saved as build-fuzz/fuzz/<harness>-crash-* (or leak-, oom-,
# timeout-): reproduce with build-fuzz/fuzz/fuzz_<harness> FILE, then commit it to
# tests/fuzz/regressions/<harness>/ with the fix.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${FUZZ_BUILD:-$root/build-fuzz}"
seconds="${1:-15}"
jobs="$(nproc 2>/dev/null || echo 2)"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-5G}"

start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DSTRATAMESH_FUZZ=ON -DSTRATAMESH_BUILD_GUI=OFF -DSTRATAMESH_FUZZ_SECONDS="$seconds" \
    -DSTRATAMESH_FUZZ_SEED="${FUZZ_SEED:-0}" >/dev/null
cmake --build "$build" -j "$jobs" --target fuzz
built=$(date +%s)
echo "fuzz: harnesses built in $((built - start)) s"

status=0
ctest --test-dir "$build" -L fuzz --output-on-failure -j "$jobs" || status=$?
end=$(date +%s)

# libFuzzer's final stats of each timed run, from CTest's log.
log="$build/Testing/Temporary/LastTest.log"
if [[ -f "$log" ]]; then
    awk '/^[0-9]+\/[0-9]+ Test: fuzz_/ { name = $3 }
         /stat::number_of_executed_units:/ { runs[name] = $2 }
         /stat::peak_rss_mb:/ { rss[name] = $2 }
         END { for (n in runs) printf "fuzz: %-20s %9d runs, peak %4d MB\n", n, runs[n], rss[n] }' \
        "$log" | sort
fi
shopt -s nullglob
for finding in "$build"/fuzz/*-crash-* "$build"/fuzz/*-leak-* "$build"/fuzz/*-oom-* \
    "$build"/fuzz/*-timeout-* "$build"/fuzz/*-slow-unit-*; do
    echo "fuzz: finding $finding" >&2
done
echo "fuzz: ran in $((end - built)) s (${seconds} s per harness, $jobs at a time)"
exit "$status"
