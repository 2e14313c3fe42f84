#!/usr/bin/env bash
# Benchmark of vesica-compare, one JSON object:
#  - ICS parameters + model-vs-measured metrics + report for the shared recording against a
#    synthetic history (target < 1 s);
#  - when the calibration is built: a one-parameter calibration of mu on a 2,312-triangle
#    spherical wall against a simulated truth (bench_compare_calibration; target < 60 s);
#  - with ../shared (or $VESICA_SHARED_DIR): the full calibration of the shared recording
#    (filling and voiding, $VESICA_BENCH_CALIBRATE parameters, at most 6) on the
#    2,474-triangle CT wall of the README (target < 60 s on 2 cores), every fitted
#    parameter with its 95 % interval and whether the data identify it;
#  - with a wall mesh in $VESICA_BENCH_WALL, the calibration of mu on that mesh.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
bin="$build/bin"
exe="$bin/vesica-compare"
data="$here/tests/compare/data"
shared="${VESICA_SHARED_DIR:-$here/../shared}"
# The detrusor-voided default wall: its fibers from filling first, then its contractility,
# the drive's latency, the sphincter's recovery and the urethra's closing pressure from voiding
# (docs/compare.md).
calibrate="${VESICA_BENCH_CALIBRATE:-mu,k1,activation_delay,urethra_recovery_half,p_close,hill_vmax}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "WALL CPU": seconds taken by the command and the CPU seconds of its processes.
timed() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
t0 = time.monotonic()
rc = subprocess.call(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
u = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{time.monotonic() - t0:.2f} {u.ru_utime + u.ru_stime:.2f}")
sys.exit(rc)
PY
}

seconds() {  # seconds taken by the command
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || return 1
  t1=$(date +%s.%N)
  echo "$t1 - $t0" | bc -l
}

report_s=$(seconds "$exe" --measured "$data/normal-female-34y.csv" \
  --simulated "$data/synthetic-history.csv" -o "$work/report")
cal_json=null
sphere_json=null
ct_json=null
if [ -x "$build/bin/bench_compare_calibration" ]; then
  sphere_json=$("$build/bin/bench_compare_calibration" 2>/dev/null | tail -1) || sphere_json=null
fi
label="$shared/data/ct/abdomen-3mm/bladder-reference.nii.gz"
if [ -f "$label" ] && [ -x "$bin/vesica-surface" ] && [ -x "$bin/vesica-mesh" ]; then
  "$bin/vesica-surface" "$label" -o "$work/ct.vtp" --target-triangles 2300 --outlet auto \
    --outlet-radius-mm 12 >/dev/null 2>&1
  "$bin/vesica-mesh" "$work/ct.vtp" -o "$work/ct.msh" --thickness-mm 3 >/dev/null 2>&1
  if ct_t=$(timed "$exe" --measured "$data/normal-female-34y.csv" --mesh "$work/ct.vtu" \
      --calibrate "$calibrate" -o "$work/ct-cal"); then
    ct_json=$(python3 - "$work/ct-cal/metrics.json" $ct_t <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["calibration"]
v = c.get("voiding") or {}
print(json.dumps({
    "triangles": 2474, "seconds": float(sys.argv[2]), "cpu_seconds": float(sys.argv[3]),
    "target_seconds": 60,
    "parameters": [{k: p[k] for k in ("name", "unit", "value", "ci95_low", "ci95_high",
                                      "identifiable", "note")} for p in c["parameters"]],
    "status": c["status"], "fitted": c["fitted"],
    "simulations": c["simulations"], "failed_simulations": c["failed_simulations"],
    "stages": [{k: s[k] for k in ("name", "model", "simulations", "seconds")} for s in c["stages"]],
    "series_rmse": {s["name"]: {"rmse": s["rmse"], "line": s["line_baseline_rmse"],
                                "constant": s["constant_baseline_rmse"]} for s in c["series"]},
    "voiding": {k: v.get(k) for k in ("qmax_ml_s", "flow_time_s", "voided_ml", "pdet_qmax_cmh2o",
                                      "flow_correlation_aligned_onsets")},
}))
PY
)
  fi
fi
if [ -n "${VESICA_BENCH_WALL:-}" ] && [ -f "$VESICA_BENCH_WALL" ]; then
  if cal_s=$(seconds "$exe" --measured "$data/normal-female-34y.csv" --mesh "$VESICA_BENCH_WALL" \
      --calibrate mu --fit-volume-ml 50,350 --material neo-hookean --residual-ml 50 \
      -o "$work/cal" --report "$work/cal.json"); then
    cal_json=$(python3 -c "import json,sys; s=json.load(open('$work/cal.json')); \
print(json.dumps({'seconds': $cal_s, 'fitted_mu_kpa': s.get('fitted_mu'), \
'fit_rmse_cmh2o': s.get('fit_rmse_cmh2o')}))")
  fi
fi
python3 - "$work/report/metrics.json" "$report_s" "$cal_json" "$sphere_json" "$ct_json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
p = m["measured"]["parameters"]
print(json.dumps({
    "report_seconds": round(float(sys.argv[2]), 4),
    "report_target_seconds": 1.0,
    "capacity_ml": p["capacity_ml"], "qmax_ml_s": p["qmax_ml_s"],
    "pdet_qmax_cmh2o": p["pdet_qmax_cmh2o"], "compliance_ml_per_cmh2o": p["compliance_ml_per_cmh2o"],
    "booi": p["booi"], "bci": p["bci"],
    "flagged_rows": [a["line"] for a in m["measured"]["artefacts"]],
    "pdet_rmse_vs_synthetic_cmh2o": m["comparison"]["filling_pdet"]["rmse_cmh2o"],
    "calibration_mesh": json.loads(sys.argv[3]),
    "calibration_sphere_2312_triangles": json.loads(sys.argv[4]),
    "calibration_whole_recording_ct_2474_triangles": json.loads(sys.argv[5]),
}, indent=2))
PY
