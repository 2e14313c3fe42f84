#!/usr/bin/env bash
# Issue 25 benchmark: vesica-simulate's pressure-steps verification protocol on sphere
# phantoms of ≈ 2,400, 9,700 and 38,700 triangles (bench/simulate/bench_verification.cpp).
# Prints one JSON object. VESICA_BENCH_LARGE=0 leaves the 38,700-triangle sphere out.
# Usage: bench_verification.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
exe="$build/bin/bench_verification"
if [ ! -x "$exe" ]; then
  echo '{"error": "bench_verification not built (cmake --build BUILD --target bench_verification)"}'
  exit 0
fi
if [ "${VESICA_BENCH_LARGE:-1}" = 1 ]; then "$exe" all; else "$exe" small; fi
