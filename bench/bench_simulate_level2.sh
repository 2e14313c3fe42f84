#!/usr/bin/env bash
# Issue 22 benchmark: a complete level-2 (Navier–Stokes urine, monolithic with the wall)
# cystometry of the real CT bladder of ../shared at the thesis's resolution: the reference
# label -> a ≈ 2,300-triangle wall with its outlet patch at the neck (vesica-surface) ->
# ≈ 22,000 urine tetrahedra (vesica-mesh --fluid --tet-size-mm 4.5) -> vesica-simulate
# --level 2: 50 -> 350 ml at 50 ml/min (360 s of simulated time), then voiding by the
# detrusor of the default (bladder) wall in adaptive steps to the post-void residual (level 1
# below the stress-free volume, docs/navier-stokes.md §8). Targets: the
# filling computed in less than its 360 simulated seconds, and the whole cystometry in less
# than its own simulated duration; the JSON reports both ratios simulated / compute time.
# Prints one JSON object: mesh sizes, the seconds of the settle (level 1, 45 -> 50 ml),
# filling and voiding phases, steps, Newton iterations and linear-solver counts, remeshes,
# and the read-outs. Usage: bench_simulate_level2.sh BUILD_DIR [OUTDIR]
# Environment: LEVEL2_CAPACITY_ML (350), LEVEL2_LINEAR_SOLVER (krylov|direct),
# LEVEL2_FLUID_DT_S (0: adaptive), LEVEL2_VOID_DT_S (0: adaptive), LEVEL2_NO_VOID (set:
# filling only), LEVEL2_DRIVE (detrusor; straining: the neo-Hookean 3 kPa wall strained by
# 4 kPa, the earlier benchmark), LEVEL2_MAX_VOID_S (120).
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
label="${VESICA_SHARED_DIR:-$here/../shared}/data/ct/abdomen-3mm/bladder-reference.nii.gz"
for tool in vesica-surface vesica-mesh vesica-simulate; do
  [ -x "$build/bin/$tool" ] || { echo "{\"error\": \"$tool not built\"}"; exit 0; }
done
[ -f "$label" ] || { echo "{\"error\": \"missing $label\"}"; exit 0; }
work=${2:-$(mktemp -d)}
mkdir -p "$work"

"$build/bin/vesica-surface" "$label" -o "$work/bladder.vtp" --target-triangles 2300 \
  --outlet auto --outlet-radius-mm 12 --json > "$work/surface.json"
"$build/bin/vesica-mesh" "$work/bladder.vtp" -o "$work/bladder.msh" --fluid --tet-size-mm 4.5 \
  --json > "$work/mesh.json"
t0=$(date +%s%N)
capacity=${LEVEL2_CAPACITY_ML:-350}
extra=()
[ -n "${LEVEL2_NO_VOID:-}" ] && extra+=(--no-void)
if [ "${LEVEL2_DRIVE:-detrusor}" = straining ]; then
  extra+=(--material neo-hookean --mu-kpa 3 --drive straining --straining-kpa 4)
else
  extra+=(--drive detrusor)
fi
"$build/bin/vesica-simulate" "$work/bladder.vtu" -o "$work/level2" --level 2 \
  --capacity-ml "$capacity" --residual-ml 45 --max-void-s "${LEVEL2_MAX_VOID_S:-120}" \
  --linear-solver "${LEVEL2_LINEAR_SOLVER:-krylov}" --fluid-dt-s "${LEVEL2_FLUID_DT_S:-0}" \
  --void-dt-s "${LEVEL2_VOID_DT_S:-0}" \
  "${extra[@]}" --json > "$work/simulate.json" || true
t1=$(date +%s%N)

python3 - "$work" "$t0" "$t1" <<'PY'
import json, sys
work, t0, t1 = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
s = json.load(open(f"{work}/level2/summary.json"))
phases = s.get("phase_compute_s", {})
# Simulated durations: filling from the infused volume at 50 ml/min; voiding from the
# history's last row after capacity.
filling_sim = (s.get("capacity_ml", 50.0) - 50.0) / 50.0 * 60.0
# history.csv: comment lines (which drive voided), the column names, then the rows.
rows = [r for r in open(f"{work}/level2/history.csv").read().split("\n")
        if r.strip() and not r.startswith("#")][1:]
end_time = max(float(r.split(",")[0]) for r in rows)
voiding_sim = max(0.0, end_time - filling_sim)
compute = sum(v for v in phases.values() if v)
ratio = lambda sim, comp: sim / comp if comp else None
out = {
    "level2_real_bladder": {
        "triangles": s.get("triangles"), "tetrahedra": s.get("tetrahedra"),
        "urine_nodes": s.get("urine_nodes"), "completed": s.get("completed"),
        "failure": s.get("failure"),
        "settle_level1_s": phases.get("settle"), "filling_s": phases.get("filling"),
        "voiding_s": phases.get("voiding"), "total_s": (t1 - t0) / 1e9,
        "filling_target_s": filling_sim,
        "filling_simulated_s": filling_sim, "voiding_simulated_s": voiding_sim,
        "filling_simulated_per_compute": ratio(filling_sim, phases.get("filling")),
        "cystometry_simulated_per_compute": ratio(filling_sim + voiding_sim, compute),
        "level1_from": s.get("level1_from"),
        "newton": s.get("newton"), "remeshes": s.get("remeshes"),
        "final_tetrahedra": s.get("final_tetrahedra"),
        "min_tet_radius_ratio": s.get("min_tet_radius_ratio"),
        "pdet_at_capacity_cmh2o": s.get("pdet_at_capacity_cmh2o"),
        "qmax_ml_s": s.get("qmax_ml_s"), "voided_ml": s.get("voided_ml"),
        "pvr_ml": s.get("pvr_ml"), "max_velocity_mm_s": s.get("max_velocity_mm_s"),
        "max_wall_shear_pa": s.get("max_wall_shear_pa"),
        "mass_balance_error_max_rel": s.get("mass_balance_error_max_rel"),
        "voiding_drive": s.get("voiding_drive"), "jet": s.get("jet"),
        "voiding_rows": sum(1 for r in rows if float(r.split(",")[0]) > filling_sim + 1e-9),
        "outputs": f"{work}/level2",
    }
}
print(json.dumps(out, indent=2))
PY
