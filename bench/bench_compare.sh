#!/usr/bin/env bash
# Benchmark of vesica-compare: ICS parameters + model-vs-measured metrics + report for the
# shared recording against a synthetic history (target < 1 s) and, when the calibration is
# built, a one-parameter calibration of mu on a 2,312-triangle spherical wall
# (bench_compare_calibration; target < 60 s) and, with a wall mesh in $VESICA_BENCH_WALL,
# the same through vesica-compare on that mesh. Prints one JSON object.
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
exe="$build/bin/vesica-compare"
data="$here/tests/compare/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

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
if [ -x "$build/bin/bench_compare_calibration" ]; then
  sphere_json=$("$build/bin/bench_compare_calibration" 2>/dev/null | tail -1) || sphere_json=null
fi
if [ -n "${VESICA_BENCH_WALL:-}" ] && [ -f "$VESICA_BENCH_WALL" ]; then
  if cal_s=$(seconds "$exe" --measured "$data/normal-female-34y.csv" --mesh "$VESICA_BENCH_WALL" \
      --calibrate mu --fit-volume-ml 50,350 -o "$work/cal" --report "$work/cal.json"); then
    cal_json=$(python3 -c "import json,sys; s=json.load(open('$work/cal.json')); \
print(json.dumps({'seconds': $cal_s, 'fitted_mu_kpa': s.get('fitted_mu'), \
'fit_rmse_cmh2o': s.get('fit_rmse_cmh2o')}))")
  fi
fi
python3 - "$work/report/metrics.json" "$report_s" "$cal_json" "$sphere_json" <<'PY'
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
}, indent=2))
PY
