#!/usr/bin/env bash
# Segment-stage benchmark: prints one JSON object on stdout.
#  - read + segment of a 512x512x300 int16 DICOM series (phantom at 0.8 mm), target < 10 s;
#  - read + segment of a 512x512x40 T2-weighted MR series (phantom, 0.7 x 0.7 x 3.5 mm,
#    +-30 % bias field, Rician noise), target < 10 s, repeated (REPEATS, default 5): the
#    best, median and worst wall time, and the CPU seconds of each run (the machine is
#    shared, so wall time above CPU time / cores is other people's load);
#  - segmentation alone of the real 3 mm CT (../shared), target < 1 s;
#  - peak resident memory of each run (getrusage ru_maxrss of the child).
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
bin="$build/bin"
here=$(cd "$(dirname "$0")" && pwd)
shared="${VESICA_SHARED_DIR:-$here/../../shared}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The phantom series is input data, not part of the timing.
"$bin/vesica-phantom" -o "$work/ct" --spacing-mm 0.8 --fov-mm 409.6,409.6,240 \
  --bladder-ml 300 --report "$work/phantom.json" 2>/dev/null
"$bin/vesica-phantom" -o "$work/mr" --modality mr --shape ellipsoid --spacing-mm 0.7 \
  --slice-spacing-mm 3.5 --fov-mm 358.4,358.4,140 --bladder-ml 300 \
  --report "$work/mr-phantom.json" 2>/dev/null

python3 - "$bin" "$work" "$shared" "${REPEATS:-5}" <<'PY'
import json, os, statistics, subprocess, sys, time
bin_dir, work, shared, repeats = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])

def run(args):
    """Runs vesica-segment; returns its summary, wall seconds, peak RSS in MB and CPU
    seconds (ru_maxrss and ru_utime + ru_stime of that child alone, from wait4)."""
    start = time.monotonic()
    proc = subprocess.Popen([os.path.join(bin_dir, "vesica-segment")] + args + ["--json"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    if status != 0:
        raise SystemExit("vesica-segment failed: %s" % " ".join(args))
    run.cpu_s = usage.ru_utime + usage.ru_stime
    return json.loads(out), wall, usage.ru_maxrss / 1024.0

truth = json.load(open(os.path.join(work, "phantom.json")))
seed = ",".join("%.3f" % v for v in truth["bladder_center_mm"])
summary, wall, rss = run([os.path.join(work, "ct"), "-o", os.path.join(work, "b.nii.gz"),
                     "--seed", seed])
result = {
    "phantom_512x512x300_0p8mm": {
        "image_size": summary["image_size"],
        "read_s": summary["timings_s"]["read"],
        "segment_s": summary["timings_s"]["segment"],
        "read_plus_segment_s": summary["timings_s"]["read"] + summary["timings_s"]["segment"],
        "wall_s": wall,
        "volume_ml": summary["volume_ml"],
        "exact_volume_ml": truth["bladder_volume_ml"],
        "peak_rss_mb": rss,
        "target_s": 10.0,
    }
}
mr_truth = json.load(open(os.path.join(work, "mr-phantom.json")))
mr_seed = ",".join("%.3f" % v for v in mr_truth["bladder_center_mm"])
runs = []
for _ in range(repeats):
    s, wall, rss = run([os.path.join(work, "mr"), "-o", os.path.join(work, "mr.nii.gz"),
                        "--seed", mr_seed])
    runs.append({"read_plus_segment_s": s["timings_s"]["read"] + s["timings_s"]["segment"],
                 "wall_s": wall, "cpu_s": run.cpu_s, "peak_rss_mb": rss,
                 "bias_field_s": s["steps"]["step_seconds"]["mr_bias_field"],
                 "volume_ml": s["volume_ml"]})
times = [r["read_plus_segment_s"] for r in runs]
result["mr_512x512x40_0p7x0p7x3p5mm"] = {
    "image_size": s["image_size"],
    "repeats": repeats,
    "read_plus_segment_s": {"best": min(times), "median": statistics.median(times),
                            "worst": max(times)},
    "cpu_s": [r["cpu_s"] for r in runs],
    "bias_field_s": [r["bias_field_s"] for r in runs],
    "volume_ml": runs[0]["volume_ml"],
    "exact_volume_ml": mr_truth["bladder_volume_ml"],
    "peak_rss_mb": max(r["peak_rss_mb"] for r in runs),
    "target_s": 10.0,
}
ct = os.path.join(shared, "data", "ct", "abdomen-3mm", "ct.nii.gz")
if os.path.exists(ct):
    s, wall, rss = run([ct, "-o", os.path.join(work, "ct3.nii.gz"), "--seed", "-2,-170,147.5"])
    result["real_ct_3mm"] = {
        "segment_s": s["timings_s"]["segment"],
        "read_s": s["timings_s"]["read"],
        "volume_ml": s["volume_ml"],
        "peak_rss_mb": rss,
        "target_s": 1.0,
    }
print(json.dumps(result, indent=2))
PY
