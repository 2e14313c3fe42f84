#!/usr/bin/env bash
# Issue 38 benchmark: FEBio 4 (../shared/tools/febio) on vesica's exports of the thin
# balloon and the default wall's filling (bench/simulate/bench_febio.py, the cases of
# tests/simulate/FebioCrossCheckTest.py): vesica's and FEBio's times, FEBio's equations,
# nonzeros and iterations, and how far FEBio's pressure lies from vesica's at equal volume.
# Prints one JSON object ({"skipped": ...} without FEBio).
# Usage: bench_febio.sh BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
exec /usr/bin/python3 "$here/simulate/bench_febio.py" "${1:-build}"
