#!/usr/bin/env bash
# Rounds of the speed benchmarks of issues 3 and 4 on a shared machine: each round runs case (a),
# then the same case with a baseline binary (another build, e.g. of an older commit) if one is
# given, then our remesh, and prints one line per round with each run's time and the CPU steal
# ticks (/proc/stat) during it. The machine's load changes from minute to minute; comparing runs
# of the same round, and keeping the rounds with little steal, separates the code from the load.
#
# usage: scripts/bench-rounds.sh [--bench build/bin/stratamesh-bench] [--baseline OTHER-BENCH]
#                                [--data-dir ../shared/data] [--rounds 10] [--pause 30]
# Each line: time, (a) optimisation seconds and its steal, baseline (a) and its steal, remesh
# total, sampling and mesh-building seconds and its steal.
set -euo pipefail

bench=build/bin/stratamesh-bench baseline="" data="${STRATAMESH_DATA_DIR:-../shared/data}" rounds=10 pause=30
while [ $# -gt 0 ]; do
  case "$1" in
    --bench) bench=$2; shift 2 ;;
    --baseline) baseline=$2; shift 2 ;;
    --data-dir) data=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --pause) pause=$2; shift 2 ;;
    *) echo "usage: $0 [--bench B] [--baseline B] [--data-dir D] [--rounds N] [--pause S]" >&2; exit 2 ;;
  esac
done
[ -x "$bench" ] || { echo "$0: no benchmark binary at $bench (build it first)" >&2; exit 1; }
[ -f "$data/modelA5.ml" ] || { echo "$0: $data/modelA5.ml is missing (set --data-dir)" >&2; exit 1; }

steal() { awk '/^cpu /{print $9}' /proc/stat; }
# Runs "$@", prints its chosen figures (awk program in $figures) and the steal ticks during it.
measure() {
  local before after out
  before=$(steal)
  out=$("$@" 2>&1 | awk "$figures")
  after=$(steal)
  echo "$out steal $((after - before))"
}

for ((r = 1; r <= rounds; ++r)); do
  figures='/optimisation .* total/{print $2 " s"}'
  a=$(measure "$bench" --case a --threads 2 --neighbours nearest --data-dir "$data")
  old="-"
  [ -z "$baseline" ] || old=$(measure "$baseline" --case a --threads 2 --neighbours nearest --data-dir "$data")
  figures='/^  ours/{t=$6} /^    sampling/{s=$2; m=$6} END{print t " s (sampling " s " s, mesh " m " s)"}'
  remesh=$(measure "$bench" --case remesh --threads 2 --data-dir "$data")
  echo "$(date +%H:%M:%S)  a: $a  |  baseline a: $old  |  remesh: $remesh"
  [ "$r" -eq "$rounds" ] || sleep "$pause"
done
