#!/bin/bash
# The installed vesica runs the demo pipeline from the install's share/ folder with nothing
# of the build or source tree reachable: no PATH to it, no environment, started from an
# empty folder; and no installed file names the build or source tree.
# Usage: installed_demo.sh SOURCE_DIR BUILD_DIR PREFIX WORK_DIR
set -euo pipefail
source=$1 build=$2 prefix=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
# Binaries and package files must not point back at the trees (RUNPATH, data paths).
for tree in "$build" "$source"; do
  if grep -rlF "$tree" "$prefix/bin" "$prefix/share/vesica" "$prefix/lib/cmake"; then
    echo "installed files above name $tree"
    exit 1
  fi
done
cd "$work"
env -i PATH=/usr/bin:/bin HOME="$work" "$prefix/bin/vesica" run \
  "$prefix/share/vesica/pipelines/demo.yaml" --workdir demo --json >run.json
for f in demo/bladder.vtu demo/sim/history.csv demo/report/index.html demo/report/metrics.json; do
  test -s "$f" || { echo "missing output $f"; cat run.json; exit 1; }
done
grep -q '"ok": *true' run.json || { cat run.json; exit 1; }
echo "installed demo: $(grep -c . demo/sim/history.csv) history rows, report written"
