#!/usr/bin/env bash
# Times the neobladder what-if study (pipelines/neobladder-whatif.yaml: 12 variants, ileum
# length x folding, each surface -> mesh -> simulate, the MR-derived pouch beside them, and
# each pouch filled again at both ends of the wall's uncertainty) end to end with `vesica run -j 2
# --keep-going` in a fresh workdir, then (when every variant completed) a second, no-op
# run. Targets (issue 34): < 600 s end to end on 2 cores, the no-op rerun < 1 s. Prints one
# JSON object: total and no-op seconds, the seconds of each stage copy and their sum per
# stage, and each variant's status and read-outs from study.csv (units in the column names).
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
vesica="$build/bin/vesica"
for tool in vesica vesica-phantom vesica-segment vesica-surface vesica-mesh vesica-simulate; do
  [ -x "$build/bin/$tool" ] || { echo "{\"error\": \"$tool not built\"}"; exit 0; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

t0=$(date +%s%N)
"$vesica" run "$here/pipelines/neobladder-whatif.yaml" --workdir "$work" -j 2 --keep-going \
  --json > "$work/run.json" || true
t1=$(date +%s%N)
# A failed stage is missing next time (it reruns), so the no-op run is timed only when
# every variant completed.
echo '{"ran": null}' > "$work/noop.json"
if grep -q '"ok": true' "$work/run.json"; then
  "$vesica" run "$here/pipelines/neobladder-whatif.yaml" --workdir "$work" -j 2 --json \
    > "$work/noop.json" || true
fi
t2=$(date +%s%N)

python3 - "$work" "$t0" "$t1" "$t2" <<'PY'
import csv, json, sys
work, t0, t1, t2 = sys.argv[1], *map(int, sys.argv[2:])
run = json.load(open(f"{work}/run.json"))
noop = json.load(open(f"{work}/noop.json"))
per_stage, per_copy = {}, {}
for s in run["stages"]:
    name = s["id"].split("@")[0]
    per_stage[name] = round(per_stage.get(name, 0.0) + s["seconds"], 2)
    per_copy[s["id"]] = {"seconds": round(s["seconds"], 2), "action": s["action"]}
variants = {}
with open(f"{work}/study.csv") as f:
    for row in csv.DictReader(f):
        variants[row.pop("variant")] = {k: v for k, v in row.items() if v != ""}
print(json.dumps({
    "study": "pipelines/neobladder-whatif.yaml", "jobs": 2,
    "total_s": round((t1 - t0) / 1e9, 2), "target_s": 600,
    "ok": run["ok"], "stages_ran": len(run["ran"]), "stages": len(run["stages"]),
    "stage_seconds_sum": per_stage, "stage_copies": per_copy,
    "noop_run_s": round((t2 - t1) / 1e9, 3) if noop["ran"] is not None else None,
    "noop_ran": noop["ran"],
    "variants": variants}, indent=1))
PY
