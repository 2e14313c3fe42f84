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
# The page as a surgeon opens it: headless Chromium at 1280 px (the DOM after the page's own
# checks ran), when Chromium is there.
if command -v chromium > /dev/null 2>&1 && [ -f "$work/study.html" ]; then
  timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --no-first-run --disable-dev-shm-usage --hide-scrollbars \
    --virtual-time-budget=3000 --user-data-dir="$work/profile" --window-size=1280,900 \
    --dump-dom "file://$work/study.html" > "$work/page.html" 2> /dev/null || true
fi

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
page = None
try:
    import re
    dom = open(f"{work}/page.html").read()
    body = lambda name: (re.search(r'<body[^>]*\sdata-' + name + r'="([^"]*)"', dom) or [None, None])[1]
    page = {"window_px": 1280, "overflowing": body("overflowing"), "table_right_px": body("table-right"),
            "answer": "id=\"answer-sentence\"" in dom, "robustness": "id=\"robustness-sentence\"" in dom,
            "ranked_rows": dom.count('<td class="rank">'), "bands": dom.count('class="area"'),
            "pictures": dom.count('class="pouch"')}
except OSError:
    pass
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
    "noop_ran": noop["ran"], "page": page,
    "variants": variants}, indent=1))
PY
