#!/usr/bin/env bash
# Runs every benchmark script bench/bench_*.sh against a build folder and collects their
# JSON into BUILD/bench/<name>.json, then prints one combined JSON document.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" && pwd)
mkdir -p "$build/bench"
first=1
echo "{"
for script in "$here"/bench_*.sh; do
  [ -e "$script" ] || continue
  name=$(basename "$script" .sh); name=${name#bench_}
  "$script" "$build" > "$build/bench/$name.json"
  [ $first = 1 ] || echo ","
  first=0
  printf '  "%s": ' "$name"; cat "$build/bench/$name.json"
done
echo "}"
