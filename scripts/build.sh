#!/usr/bin/env bash
# Configures and builds StrataMesh in build/ (Release, Ninja, ccache).
# Usage: scripts/build.sh [extra cmake -D options...]; BUILD_TYPE=Debug for a debug build.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
jobs="$(nproc 2>/dev/null || echo 2)"

# Paths relative to the source tree in ccache's hashes: a fresh clone reuses the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-5G}"

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" "$@"
cmake --build "$build" -j "$jobs"
if command -v ccache >/dev/null; then
    ccache --show-stats 2>/dev/null | grep -iE 'hits|misses' | head -n 3 || true
fi
