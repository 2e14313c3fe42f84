#!/bin/bash
# Test fixture: a fresh `cmake --install BUILD --prefix PREFIX`, as `make install` does.
# Usage: install_prefix.sh BUILD_DIR PREFIX
set -euo pipefail
build=$1 prefix=$2
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
test -x "$prefix/bin/vesica"
