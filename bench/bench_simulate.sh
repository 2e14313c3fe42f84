#!/usr/bin/env bash
# Simulate benchmarks (issues 6, 7): prints one JSON object. Usage: bench_simulate.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
exe="$build/bin/bench_simulate"
if [ ! -x "$exe" ]; then
  echo '{"error": "bench_simulate not built (cmake --build BUILD --target bench_simulate)"}'
  exit 0
fi
# The 17,000-triangle cystometry is the slowest case (target 60 s; its last figure is in
# docs/benchmarks.md); VESICA_BENCH_LARGE=0 leaves it out.
if [ "${VESICA_BENCH_LARGE:-1}" = 1 ]; then "$exe" all; else "$exe" balloon-and-small; fi
