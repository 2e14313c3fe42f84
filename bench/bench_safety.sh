#!/usr/bin/env bash
# Benchmark of the refusals of hostile inputs (issue 37), one JSON object. Each case is
# built here and given to the stage that reads it, measured with /usr/bin/time -v: wall
# time, peak resident memory, exit code and whether the refusal is one line. The
# acceptance: every refusal one line within 5 s and 1 GB for inputs up to 100 MB
# (`within_limits`). Also measured: a 2-million-row recording accepted (time, memory, page
# size) and how long vesica-simulate takes to stop after SIGTERM on a fine wall, and
# whether it leaves its checkpoint (`stop`).
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$build/bin" "$here" "$work" <<'PY'
import gzip, json, math, os, re, signal, struct, subprocess, sys, time

bin_dir, repo, work = sys.argv[1:]
os.chdir(work)
exe = lambda name: os.path.join(bin_dir, name)
recording = os.path.join(repo, "tests/compare/data/normal-female-34y.csv")


def measured(argv, deadline=120):
    """(seconds, peak RSS in MB, exit code, output) of argv under /usr/bin/time -v."""
    t0 = time.monotonic()
    p = subprocess.run(["/usr/bin/time", "-v"] + argv, capture_output=True, text=True,
                       errors="replace", timeout=deadline)
    seconds = time.monotonic() - t0
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
    output = p.stdout + p.stderr[: p.stderr.find("\tCommand being timed")]
    # time's own line about the exit status is not the program's output
    output = "\n".join(l for l in output.splitlines()
                       if not l.startswith("Command exited with non-zero status")
                       and not l.startswith("Command terminated by signal"))
    return seconds, int(rss.group(1)) / 1024 if rss else None, p.returncode, output


def refusal(name, argv, input_bytes):
    seconds, rss, code, output = measured(argv)
    lines = [l for l in output.splitlines() if l.strip()]
    one_line = len(lines) == 1 and "error" in lines[0] and len(lines[0]) <= 300
    return {"case": name, "input_mb": round(input_bytes / 2**20, 3), "seconds": round(seconds, 2),
            "peak_rss_mb": round(rss, 1) if rss else None, "exit_code": code,
            "one_line": one_line, "within_limits": one_line and code in (1, 2) and seconds < 5
            and (rss or 0) < 1024}


def edited_recording(path, edit, first_line=None):
    with open(recording) as f, open(path, "w") as o:
        header = False
        if first_line:
            o.write(first_line + "\n")
        for line in f:
            if line.startswith("#") or not header:
                header = header or not line.startswith("#")
                o.write(line)
                continue
            cells = line.rstrip("\n").split(",")
            edit(cells)
            o.write(",".join(cells) + "\n")


def nifti(path, dims, data=b"", opener=open):
    h = bytearray(352)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, 3, *dims, 1, 1, 1, 1)
    struct.pack_into("<hh", h, 70, 2, 8)
    struct.pack_into("<8f", h, 76, 1, 2, 2, 2, 1, 1, 1, 1)
    struct.pack_into("<ff", h, 108, 352, 1)
    h[344:348] = b"n+1\0"
    with opener(path, "wb") as f:
        f.write(bytes(h))
        if callable(data):
            data(f)
        else:
            f.write(data)


cases = []
size = lambda p: os.path.getsize(p) if os.path.exists(p) else 0

os.mkfifo("fifo.csv")
cases.append(refusal("named pipe as a recording", [exe("vesica-compare"), "--measured", "fifo.csv", "-o", "r"], 0))
cases.append(refusal("/dev/zero as a recording", [exe("vesica-compare"), "--measured", "/dev/zero", "-o", "r"], 0))

subprocess.run([exe("vesica-surface"), "-o", "sphere.vtp", "--shape", "sphere", "--volume-ml", "100",
                "--edge-mm", "8"], check=True, capture_output=True)
vtp = open("sphere.vtp", "rb").read()
long_count = re.sub(rb'NumberOfPoints="\d+"', b'NumberOfPoints="' + b"7" * 30000 + b'"', vtp, count=1)
open("count.vtp", "wb").write(long_count)
cases.append(refusal("VTP count of 30,000 digits", [exe("vesica-mesh"), "count.vtp", "-o", "m.msh"], size("count.vtp")))
import base64
data = vtp.index(b"_", vtp.index(b"<AppendedData")) + 1
words = bytearray(base64.b64decode(vtp[data:data + 16]))
struct.pack_into("<I", words, 0, 0xF0000000)
open("blocks.vtp", "wb").write(vtp[:data] + base64.b64encode(bytes(words)) + vtp[data + 16:])
cases.append(refusal("VTP zlib block count 0xF0000000", [exe("vesica-mesh"), "blocks.vtp", "-o", "m.msh"], size("blocks.vtp")))

edited_recording("header.csv", lambda c: None, "# " + "x" * 70000)
cases.append(refusal("recording header line of 70,000 characters", [exe("vesica-compare"), "--measured", "header.csv", "-o", "r", "--no-pdf"], size("header.csv")))
def stuck(c):
    c[0] = "00:00"
edited_recording("stuck.csv", stuck)
cases.append(refusal("recording whose time never advances", [exe("vesica-compare"), "--measured", "stuck.csv", "-o", "r", "--no-pdf"], size("stuck.csv")))
def pascal(c):
    for k in (2, 3, 4):
        c[k] = str(float(c[k]) * 98.0665)
edited_recording("pascal.csv", pascal)
cases.append(refusal("recording in Pa labelled cmH2O", [exe("vesica-compare"), "--measured", "pascal.csv", "-o", "r", "--no-pdf"], size("pascal.csv")))
with open("rows.csv", "w") as o:  # 100 MB, 3.6 million rows: more than a recording may have
    o.write("time_s,pves_cmh2o,pabd_cmh2o,infused_ml\n")
    row, i = "", 0
    while o.tell() < 100 * 2**20:
        o.write("".join(f"{0.01 * k:.2f},{12 + k % 7},10,{k * 1e-4:.4f}\n" for k in range(i, i + 10000)))
        i += 10000
cases.append(refusal("recording of 100 MB, 3.6 million rows", [exe("vesica-compare"), "--measured", "rows.csv", "-o", "r", "--no-pdf"], size("rows.csv")))

subprocess.run([exe("vesica-phantom"), "-o", "ct", "--spacing-mm", "8", "--bladder-ml", "150"], check=True, capture_output=True)
for name in os.listdir("ct"):
    if not name.endswith(".dcm"):
        continue
    b = bytearray(open(os.path.join("ct", name), "rb").read())
    for element in (0x10, 0x11):
        at = b.index(bytes([0x28, 0, element, 0, 2, 0, 0, 0]))
        b[at + 8:at + 10] = b"\xff\xff"
    open(os.path.join("ct", name), "wb").write(bytes(b))
cases.append(refusal("DICOM series claiming 65535 x 65535 pixels", [exe("vesica-segment"), "ct", "-o", "b.nii.gz"], sum(size(os.path.join("ct", n)) for n in os.listdir("ct"))))

nifti("claims.nii", (1000, 1000, 1000), bytes(1000))
cases.append(refusal("NIfTI header claiming 1000^3 voxels (surface)", [exe("vesica-surface"), "claims.nii", "-o", "s.vtp"], size("claims.nii")))
cases.append(refusal("NIfTI header claiming 1000^3 voxels (segment)", [exe("vesica-segment"), "claims.nii", "-o", "b.nii.gz"], size("claims.nii")))
zeros = bytes(1 << 20)
def fill(f):
    for _ in range(700 * 700 * 700 // len(zeros) + 1):
        f.write(zeros)
nifti("whole.nii.gz", (700, 700, 700), fill, lambda p, m: gzip.open(p, m, compresslevel=1))
cases.append(refusal("complete 700^3 NIfTI (.nii.gz)", [exe("vesica-surface"), "whole.nii.gz", "-o", "s.vtp"], size("whole.nii.gz")))

n = 40
inverted = bytes(0 if math.dist((i, j, k), (20, 20, 20)) <= 12 else 1 for k in range(n) for j in range(n) for i in range(n))
nifti("inverted.nii", (n, n, n), inverted)
cases.append(refusal("inverted label map", [exe("vesica-surface"), "inverted.nii", "-o", "s.vtp"], size("inverted.nii")))
with open("um.obj", "w") as o:
    r = 30000
    o.write(f"v {r} 0 0\nv {-r} 0 0\nv 0 {r} 0\nv 0 {-r} 0\nv 0 0 {r}\nv 0 0 {-r}\n")
    o.write("f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n")
cases.append(refusal("surface in micrometres", [exe("vesica-mesh"), "um.obj", "-o", "m.msh"], size("um.obj")))

# A recording of 2 million rows (a 100 Hz study of 5.6 hours) is accepted: every sample in
# the analysis, the page thinned.
rows = 2000000
with open("long.csv", "w") as o:
    o.write("# long recording, female\ntime_s,pves_cmh2o,pabd_cmh2o,flow_ml_s,voided_ml,infused_ml\n")
    T, end = 0.01 * rows, 0.8 * 0.01 * rows
    for start in range(0, rows, 10000):
        chunk = []
        for k in range(start, start + 10000):
            t = 0.01 * k
            inf = 400 * min(t, end) / end
            s = (t - end) / (T - end) if t > end else 0
            chunk.append(f"{t:.2f},{12 + inf / 100 + (30 if s else 0):.2f},10.00,"
                         f"{15 * math.sin(math.pi * s) if s else 0:.2f},{380 * s:.2f},{inf:.2f}\n")
        o.write("".join(chunk))
seconds, rss, code, output = measured([exe("vesica-compare"), "--measured", "long.csv", "-o", "long", "--no-pdf"], 600)
long_recording = {"rows": rows, "input_mb": round(size("long.csv") / 2**20, 1), "seconds": round(seconds, 1),
                  "peak_rss_mb": round(rss, 1) if rss else None, "exit_code": code,
                  "page_mb": round(size("long/index.html") / 2**20, 2)}

# Stopping: SIGTERM 8 s into a simulation on a fine sphere; how long until it exits.
subprocess.run([exe("vesica-surface"), "-o", "fine.vtp", "--shape", "sphere", "--volume-ml", "80",
                "--edge-mm", "1.5"], check=True, capture_output=True)
triangles = int(re.search(rb'NumberOfPolys="(\d+)"', open("fine.vtp", "rb").read()).group(1))
p = subprocess.Popen([exe("vesica-simulate"), "fine.vtp", "-o", "sim", "--capacity-ml", "400",
                      "--no-series", "--checkpoint-minutes", "0.01"],
                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
time.sleep(8)  # well inside the filling of a wall this fine
p.send_signal(signal.SIGTERM)
t0 = time.monotonic()
try:
    p.wait(timeout=300)
except subprocess.TimeoutExpired:
    p.kill()
    p.wait()
stop = {"triangles": triangles, "sigterm_after_s": 8, "exit_after_s": round(time.monotonic() - t0, 2),
        "exit_code": p.returncode,
        "checkpoint": os.path.exists(".vesica/checkpoints/sim/checkpoint.bin"),
        "message": p.stderr.read().strip().splitlines()[-1:] }

print(json.dumps({"refusals": cases, "within_limits": all(c["within_limits"] for c in cases),
                  "long_recording": long_recording, "stop": stop}, indent=1))
PY
