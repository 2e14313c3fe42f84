#!/usr/bin/env bash
# The default cystometry (50 -> 350 ml at 50 ml/min, then the detrusor's void) on the real
# CT bladder meshed at five sizes (issue 33): whether the wall carries the void to its end
# itself (no hand-over between model levels), how much PVR and Qmax move with the mesh, and
# how the compute time grows with the triangle count (the exponent p of t ~ n^p between
# neighbouring sizes). Each mesh is also simulated with a new factorization for every Newton
# increment (--newton-krylov-solves 0, the code before issue 36), in the same run, for the
# speed-up; VESICA_BENCH_PRESENT=0 leaves that out. Usage: bench_ct_void.sh BUILD_DIR
# [TRIANGLES...]. Prints one JSON object; needs ../shared/data/ct beside the checkout.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1300 2500 4900 9800 18000)
here=$(cd "$(dirname "$0")/.." && pwd)
label="$here/../shared/data/ct/abdomen-3mm/bladder-reference.nii.gz"
[ -f "$label" ] || { echo "{\"error\": \"$label not found\"}"; exit 0; }
for tool in vesica-surface vesica-mesh vesica-simulate; do
  [ -x "$build/bin/$tool" ] || { echo "{\"error\": \"$tool not built\"}"; exit 0; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for n in "${sizes[@]}"; do
  d="$work/$n"
  mkdir -p "$d"
  "$build/bin/vesica-surface" "$label" -o "$d/wall.vtp" --target-triangles "$n" --outlet auto \
    --outlet-radius-mm 12 > /dev/null 2>&1
  "$build/bin/vesica-mesh" "$d/wall.vtp" -o "$d/wall.msh" --report "$d/mesh.json" > /dev/null 2>&1
  if [ "${VESICA_BENCH_PRESENT:-1}" = 1 ]; then
    t0=$(date +%s%N)
    "$build/bin/vesica-simulate" "$d/wall.vtu" -o "$d/present" --no-series --json \
      --newton-krylov-solves 0 > /dev/null 2>&1 || true
    t1=$(date +%s%N)
    echo $(( (t1 - t0) / 1000000 )) > "$d/present_ms"
  fi
  t0=$(date +%s%N)
  "$build/bin/vesica-simulate" "$d/wall.vtu" -o "$d/sim" --no-series --json > /dev/null 2>&1 || true
  t1=$(date +%s%N)
  echo $(( (t1 - t0) / 1000000 )) > "$d/ms"
done
python3 - "$work" "${sizes[@]}" <<'PY'
import json, math, sys
work, sizes = sys.argv[1], sys.argv[2:]
rows = []
for n in sizes:
    d = f"{work}/{n}"
    present = {}
    try:
        p = json.load(open(f"{d}/present/summary.json"))
        present = {"present_code_seconds": int(open(f"{d}/present_ms").read()) / 1000.0,
                   "present_code_qmax_ml_s": p.get("qmax_ml_s"),
                   "present_code_pvr_ml": p.get("pvr_ml")}
    except (OSError, ValueError):
        pass
    try:
        s = json.load(open(f"{d}/sim/summary.json"))
    except (OSError, ValueError):
        rows.append({"target_triangles": int(n), "error": "no summary.json"})
        continue
    mesh = json.load(open(f"{d}/mesh.json"))
    card = s.get("model_card", {})
    hand_overs = card.get("level", {}).get("hand_overs", [])
    rows.append({"target_triangles": int(n),
                 "triangles": sum(mesh.get("region_triangle_counts", {}).values()) or None,
                 "seconds": int(open(f"{d}/ms").read()) / 1000.0,
                 "completed": s.get("completed"), "qmax_ml_s": s.get("qmax_ml_s"),
                 "pvr_ml": s.get("pvr_ml"), "hand_overs": hand_overs, **present})
ok = [r for r in rows if r.get("completed")]
for a, b in zip(ok, ok[1:]):
    if a["triangles"] and b["triangles"] and a["seconds"] > 0:
        b["time_exponent_from_previous"] = round(
            math.log(b["seconds"] / a["seconds"]) / math.log(b["triangles"] / a["triangles"]), 2)
def spread(key):
    v = [r[key] for r in ok if r.get(key) is not None]
    return round(max(v) - min(v), 3) if v else None
qmax = [r["qmax_ml_s"] for r in ok if r.get("qmax_ml_s")]
print(json.dumps({
    "case": "CT bladder, default model, 50 -> 350 ml, detrusor void", "meshes": rows,
    "no_hand_over_anywhere": all(not r["hand_overs"] for r in ok) and len(ok) == len(rows),
    "pvr_spread_ml": spread("pvr_ml"), "target_pvr_spread_ml": 2,
    "qmax_spread_percent": round(100 * (max(qmax) - min(qmax)) / min(qmax), 2) if qmax else None,
    "target_qmax_spread_percent": 2, "target_time_exponent": 1.3}, indent=1))
PY
