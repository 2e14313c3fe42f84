#!/usr/bin/env bash
# Runs the benchmark scripts bench/bench_*.sh against a build folder, keeps each one's JSON
# in BUILD/bench/<name>.json beside <name>.meta.json (date, commit, machine and its load
# for that run) and <name>.log (its stderr), prints one combined JSON document, and
# regenerates the table of docs/benchmarks.md from them (bench/benchmarks_md.py).
#
# Usage: bench/run.sh [BUILD] [NAME...]
#   NAME: the part after bench_ (segment, surface, mesh, simulate, simulate_level2,
#         compare, pipelines, study, verification, build, safety); none = all.
#   VESICA_BENCH_SKIP="simulate_level2 study"  leaves those out;
#   VESICA_BENCH_KEEP=1  keeps the JSON of benchmarks not run now (their rows keep their
#                        own date and commit); by default the table is this run only, and a
#                        benchmark not run appears as "not measured in this run".
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
build=$(cd "${1:-build}" && pwd)
[ $# -gt 0 ] && shift
selected=" $* "
skipped=" ${VESICA_BENCH_SKIP:-} "
out="$build/bench"
mkdir -p "$out"
[ "${VESICA_BENCH_KEEP:-0}" = 1 ] || rm -f "$out"/*.json "$out"/*.log

commit=$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$repo" diff --quiet HEAD 2>/dev/null || commit="$commit+changes"
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)
machine="${cpu:-unknown CPU}, $(nproc) cores"
load() { cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?"; }

for script in "$here"/bench_*.sh; do
  [ -e "$script" ] || continue
  name=$(basename "$script" .sh); name=${name#bench_}
  if [ "$selected" != "  " ] && [[ "$selected" != *" $name "* ]]; then continue; fi
  if [[ "$skipped" == *" $name "* ]]; then continue; fi
  echo "bench: $name ..." >&2
  date=$(date -u +%Y-%m-%dT%H:%MZ)
  load_before=$(load)
  t0=$(date +%s)
  rc=0
  "$script" "$build" > "$out/$name.json.tmp" 2> "$out/$name.log" || rc=$?
  if [ $rc = 0 ] && python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$out/$name.json.tmp" 2>/dev/null; then
    mv "$out/$name.json.tmp" "$out/$name.json"
  else
    rm -f "$out/$name.json.tmp"
    printf '{"error": "bench_%s.sh failed (exit %s), see %s"}\n' "$name" "$rc" "$out/$name.log" > "$out/$name.json"
  fi
  seconds=$(( $(date +%s) - t0 ))
  python3 - "$out/$name.meta.json" "$date" "$commit" "$machine, load $load_before → $(load)" "$seconds" <<'PY'
import json, sys
path, date, commit, machine, seconds = sys.argv[1:]
with open(path, "w") as f:
    json.dump({"date": date, "commit": commit, "machine": machine, "script_seconds": int(seconds)}, f)
    f.write("\n")
PY
  echo "bench: $name done in ${seconds} s" >&2
done

first=1
echo "{"
for json in "$out"/*.json; do
  [ -e "$json" ] || continue
  case "$json" in *.meta.json) continue ;; esac
  [ $first = 1 ] || echo ","
  first=0
  printf '  "%s": ' "$(basename "$json" .json)"; cat "$json"
done
echo "}"
python3 "$here/benchmarks_md.py" "$out" "$repo/docs/benchmarks.md"
echo "bench: docs/benchmarks.md regenerated" >&2
