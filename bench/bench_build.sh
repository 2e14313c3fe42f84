#!/usr/bin/env bash
# The build and the test tiers as a clean clone meets them (issue 32); prints one JSON
# object. Every step reports wall time and CPU time (user + sys of all its processes, from
# /usr/bin/time), and the load average around it: the reference machine has 2 cores that
# other work may share, so CPU time is the figure that compares between runs.
#  - configure and build: a clone of this checkout's HEAD (committed work only) in
#    BUILD/bench-clone, configured by the Makefile with VESICA_SHARED_DIR pointing at this
#    checkout's ../shared, and built as `make test` builds it (every target and the
#    sanitized fuzz readers) with the compiler cache off, as in CI where it starts cold;
#  - ctest of each tier on its own, -j 2 (unit, acceptance, fuzz, install): wall, CPU,
#    entries passed / failed / skipped;
#  - the quick loop: one .cpp of simulate/src changed (a comment appended) and test_simulate
#    rebuilt until it runs;
#  - what ran: ctest entries, GoogleTest cases and the assertions the test processes
#    executed (tests/inventory.py, tests/support/AssertionCount.h); with
#    VESICA_BENCH_BEFORE=inventory.json (an earlier `inventory.py list`), whether every
#    case of that build still runs in some tier.
# Usage: bench/bench_build.sh [BUILD]   (the clone is removed unless VESICA_BENCH_KEEP_CLONE=1)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(mkdir -p "${1:-build}" && cd "${1:-build}" && pwd)
clone=$build/bench-clone
out=$build/bench/build-steps
jobs=${JOBS:-$(nproc)}
load() { cut -d' ' -f1 /proc/loadavg; }

rm -rf "$clone" "$out"
git clone -q --no-hardlinks "$repo" "$clone" >&2
mkdir -p "$out"
shared=$(cd "$repo/.." && pwd)/shared

# step NAME COMMAND...: runs it, keeps its output in BUILD/bench/build-steps/NAME.log and its figures in
# $out/NAME.time ("wall user sys load_before load_after exit").
step() {
  local name=$1 before rc=0
  shift
  before=$(load)
  echo "bench_build: $name ..." >&2
  /usr/bin/time -o "$out/$name.cpu" -f "%e %U %S" "$@" >"$out/$name.log" 2>&1 || rc=$?
  echo "$(tail -1 "$out/$name.cpu") $before $(load) $rc" >"$out/$name.time"
}

export CCACHE_DISABLE=1
step configure make -C "$clone" configure BUILD_DIR=build \
  CMAKE_ARGS="-DVESICA_SHARED_DIR=$shared"
step build make -C "$clone" build-tests BUILD_DIR=build JOBS="$jobs"
unset CCACHE_DISABLE

log=$out/assertions.log
rm -f "$log"
for tier in unit acceptance fuzz install; do
  step "ctest_$tier" env VESICA_ASSERTION_LOG="$log" \
    ctest --test-dir "$clone/build" -L "^$tier\$" -j "$jobs" --output-junit "$out/$tier.xml"
done

# The quick loop: a change to one simulation source, then the one test binary that needs it.
# The change is code, not a comment: ccache compares preprocessed sources, from which
# comments are gone, and would answer for a comment from its cache.
touched=$(cd "$clone" && find simulate/src -name 'Cystometry.cpp' | head -1)
echo "static_assert(true, \"bench_build.sh: changed at $(date +%s%N)\");" >>"$clone/$touched"
step incremental cmake --build "$clone/build" --target test_simulate

python3 "$repo/tests/inventory.py" list "$clone/build" --assertions "$log" >"$out/inventory.json"
if [ -n "${VESICA_BENCH_BEFORE:-}" ]; then
  python3 "$repo/tests/inventory.py" compare "$VESICA_BENCH_BEFORE" "$out/inventory.json" \
    >"$out/compare.json" || true
fi

python3 - "$out" "$clone" "$touched" "$jobs" <<'PY'
import json, os, sys
import xml.etree.ElementTree as ET
out, clone, touched, jobs = sys.argv[1:]

def timed(name):
    wall, user, sys_, before, after, rc = open(f"{out}/{name}.time").read().split()
    return {"wall_s": float(wall), "cpu_s": round(float(user) + float(sys_), 1),
            "load_before": float(before), "load_after": float(after), "exit": int(rc)}

def tier(name):
    d = timed(f"ctest_{name}")
    try:
        suite = ET.parse(f"{out}/{name}.xml").getroot()
        d.update({k: int(suite.get(k, 0)) for k in ("tests", "failures", "skipped")})
    except (OSError, ET.ParseError):
        d["tests"] = None
    return d

def translation_units():
    try:
        with open(f"{clone}/build/compile_commands.json") as f:
            return len(json.load(f))
    except OSError:
        return None

inventory = json.load(open(f"{out}/inventory.json"))
tiers = {t: tier(t) for t in ("unit", "acceptance", "fuzz", "install")}
result = {
    "cores": os.cpu_count(), "jobs": int(jobs), "compiler_cache": "off for configure and build",
    "configure": timed("configure"),
    "build": dict(timed("build"), translation_units=translation_units()),
    "ctest": tiers,
    "ctest_all_tiers_wall_s": round(sum(t["wall_s"] for t in tiers.values()), 1),
    "ctest_all_tiers_cpu_s": round(sum(t["cpu_s"] for t in tiers.values()), 1),
    "incremental_test_simulate": dict(timed("incremental"), touched=touched),
    "ctest_entries": inventory["ctest_entries"],
    "ctest_entries_by_tier": inventory["ctest_entries_by_tier"],
    "gtest_cases": inventory["gtest_cases"],
    "gtest_cases_run": inventory["gtest_cases_run"],
    "assertions": inventory.get("assertions"),
    "entries_without_one_tier": inventory["entries_without_one_tier"],
    "targets": {"unit_wall_s": 120, "incremental_wall_s": 60, "make_test_wall_s": 1200},
}
result["configure_build_and_tiers_wall_s"] = round(
    result["configure"]["wall_s"] + result["build"]["wall_s"] + result["ctest_all_tiers_wall_s"], 1)
if os.path.exists(f"{out}/compare.json"):
    result["against_before"] = json.load(open(f"{out}/compare.json"))
print(json.dumps(result, indent=1))
PY
[ "${VESICA_BENCH_KEEP_CLONE:-0}" = 1 ] || rm -rf "$clone"
