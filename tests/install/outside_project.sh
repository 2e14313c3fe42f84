#!/bin/bash
# A project outside the tree (tests/install/outside) configured, built and run against the
# installed prefix only: find_package(vesica) must find every library and its third-party
# dependencies from the prefix and the system, never from the build tree.
# Usage: outside_project.sh SOURCE_DIR PREFIX WORK_DIR [GENERATOR]
set -euo pipefail
source=$1 prefix=$2 work=$3 generator=${4:-Ninja}
rm -rf "$work"
mkdir -p "$work"
cmake -S "$source/tests/install/outside" -B "$work" -G "$generator" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 ||
  { tail -30 "$work/configure.log"; exit 1; }
# The package's config is the installed one.
grep -q "vesica_DIR:PATH=$prefix/" "$work/CMakeCache.txt" ||
  { echo "vesica was not found in $prefix:"; grep vesica_DIR "$work/CMakeCache.txt"; exit 1; }
cmake --build "$work" >"$work/build.log" 2>&1 || { tail -30 "$work/build.log"; exit 1; }
"$work/balloon"
