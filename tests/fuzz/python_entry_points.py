"""The Python module's entry points under hostile files and arguments (the fuzz tier).

Each reader gets a valid file of its format mutated from fixed seeds: in its structure (a
number of the header replaced by a hostile one: 2^32, 2^64, -1, NaN, 0, a 30,000-digit
count; NIfTI's header fields at their offsets), cut short, or with bytes flipped. Every case
must return or raise one of the module's refusals (vesica.Error, ValueError, TypeError,
OSError): never crash, hang or allocate without bound. Every entry point that takes
parameters gets random keys and values and must return or raise ValueError/TypeError.

Each format runs in its own interpreter, limited in time and address space, so that a crash
is that format's failure (with the case that caused it), not the session's. Run by ctest
(test_python_fuzz) with Debian's python3; VESICA_BIN_DIR names the executables and
PYTHONPATH the module."""
import gzip
import json
import os
import random
import re
import resource
import struct
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from vesica_tools import tool  # noqa: E402  (the Python tests' own helper)
RECORDING = os.path.join(HERE, "..", "..", "pipelines", "data", "normal-female-34y.csv")
CASES = 60
HOSTILE_NUMBERS = [b"4294967296", b"18446744073709551616", b"-1", b"nan", b"0", b"1e308",
                   b"999999999", b"9" * 30000]


# --- the mutations (deterministic in seed and case) ---------------------------------------

def replace_a_number(data, rng):
    """A number of the file's first 4 KB (where headers are) replaced by a hostile one."""
    numbers = [m.span() for m in re.finditer(rb"[0-9]+", data[:4096])]
    if not numbers:
        return flip_bytes(data, rng)
    start, end = rng.choice(numbers)
    return data[:start] + rng.choice(HOSTILE_NUMBERS) + data[end:]


def cut_short(data, rng):
    return data[:rng.randrange(0, max(1, len(data)))]


def flip_bytes(data, rng):
    out = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        if out:
            out[rng.randrange(len(out))] = rng.randrange(256)
    return bytes(out)


def nifti_field(data, rng):
    """A field of the 348-byte NIfTI-1 header (dims, datatype, bitpix, vox_offset, pixdim,
    scaling) set to an extreme value."""
    fields = [(40, "<h"), (42, "<h"), (44, "<h"), (46, "<h"), (70, "<h"), (72, "<h"),
              (76, "<f"), (80, "<f"), (84, "<f"), (108, "<f"), (112, "<f"), (116, "<f")]
    offset, fmt = rng.choice(fields)
    value = rng.choice([-1, 0, 32767, -32768] if fmt == "<h" else
                       [float("nan"), float("inf"), -1.0, 0.0, 1e30])
    out = bytearray(data)
    struct.pack_into(fmt, out, offset, value)
    return bytes(out)


def mutate(fmt, data, rng):
    if fmt == "nifti":
        raw = gzip.decompress(data)
        choice = rng.randrange(4)
        if choice == 3:
            return flip_bytes(data, rng)  # the compressed stream itself
        mutated = [nifti_field, cut_short, flip_bytes][choice](raw, rng)
        return gzip.compress(mutated)
    return rng.choice([replace_a_number, replace_a_number, cut_short, flip_bytes])(data, rng)


# --- the worker: one format's cases in this (limited) interpreter --------------------------

READERS = {
    "vtp": ("read_surface", ".vtp"), "stl": ("read_surface", ".stl"),
    "ply": ("read_surface", ".ply"), "obj": ("read_surface", ".obj"),
    "vtu": ("read_mesh", ".vtu"), "msh": ("read_mesh", ".msh"),
    "wall": ("load_wall", ".vtu"), "csv": ("read_recording", ".csv"),
    "ics": ("ics_parameters", ".csv"), "nifti": ("read_label_map", ".nii.gz"),
}


def work(fmt, original, scratch, seed):
    import vesica
    refusals = (vesica.Error, ValueError, TypeError, OSError)
    function, suffix = READERS[fmt]
    data = open(original, "rb").read()
    outcomes = {"returned": 0, "refused": 0}
    for case in range(CASES):
        rng = random.Random(seed * 1000 + case)
        path = os.path.join(scratch, f"case{suffix}")
        with open(path, "wb") as f:
            f.write(mutate(fmt, data, rng))
        print(f"case {case}", file=sys.stderr, flush=True)
        try:
            getattr(vesica, function)(path)
            outcomes["returned"] += 1
        except refusals:
            outcomes["refused"] += 1
    print(json.dumps(outcomes))


def random_value(rng, depth=0):
    kinds = [lambda: rng.choice([0, -1, 1e308, float("nan"), float("inf"), 2 ** 70]),
             lambda: rng.choice(["", "x" * 5000, "1e9", "nan", "bladder", "--capacity-ml"]),
             lambda: None, lambda: rng.choice([True, False]),
             lambda: [random_value(rng, depth + 1) for _ in range(rng.randint(0, 3))],
             lambda: {"k": random_value(rng, depth + 1)}]
    return rng.choice(kinds[:4] if depth > 2 else kinds)()


def work_parameters(wall_path, seed):
    import vesica
    wall = vesica.load_wall(wall_path)
    keys = [e["key"] for e in vesica.parameter_catalogue()] + [
        "capacity_ml", "fill_rate_ml_min", "level", "material", "no_void", "posture", "x",
        "", "capacity", "material.mu_kpa"]
    outcomes = {"returned": 0, "refused": 0}
    for case in range(4 * CASES):
        rng = random.Random(seed * 1000 + case)
        args = [{rng.choice(keys): random_value(rng) for _ in range(rng.randint(1, 3))}
                if rng.random() < 0.9 else random_value(rng) for _ in range(2)]
        print(f"case {case}: {args!r:.200}", file=sys.stderr, flush=True)
        try:
            vesica.model_card(wall, args[0], args[1])
            outcomes["returned"] += 1
        except (ValueError, TypeError):
            outcomes["refused"] += 1
    print(json.dumps(outcomes))


# --- the tests: one interpreter per format --------------------------------------------------

@pytest.fixture(scope="module")
def originals(tmp_path_factory):
    d = tmp_path_factory.mktemp("fuzz-originals")
    files = {"csv": RECORDING, "ics": RECORDING}
    for fmt in ("vtp", "stl", "ply", "obj"):
        files[fmt] = str(d / f"sphere.{fmt}")
        tool("vesica-surface", "-o", files[fmt], "--shape", "sphere", "--volume-ml", 50,
             "--edge-mm", 12, "--outlet", "auto")
    tool("vesica-mesh", files["vtp"], "-o", d / "sphere.msh")
    files["msh"] = str(d / "sphere.msh")
    files["vtu"] = files["wall"] = str(d / "sphere.vtu")
    tool("vesica-phantom", "-o", d / "phantom", "--bladder-ml", 50, "--spacing-mm", 3,
         "--fov-mm", "150,150,90")
    tool("vesica-segment", d / "phantom", "-o", d / "label.nii.gz")
    files["nifti"] = str(d / "label.nii.gz")
    return files


def limited():
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


def run_worker(args, tmp_path):
    try:
        r = subprocess.run([sys.executable, __file__, *args], capture_output=True, text=True,
                           timeout=240, preexec_fn=limited, env=dict(os.environ), cwd=tmp_path)
    except subprocess.TimeoutExpired as e:
        last = (e.stderr or b"").decode(errors="replace").strip().splitlines()[-1:]
        pytest.fail(f"hung at {last}")
    last = r.stderr.strip().splitlines()[-3:]
    assert r.returncode == 0, f"exit {r.returncode} at {last}"
    return json.loads(r.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("fmt", sorted(READERS))
def test_a_mutated_file_is_read_or_refused_never_a_crash(fmt, originals, tmp_path):
    outcomes = run_worker(["worker", fmt, originals[fmt], str(tmp_path), "7"], tmp_path)
    assert outcomes["returned"] + outcomes["refused"] == CASES
    assert outcomes["refused"] > 0, "no mutation was refused: the cases did not reach the reader"


def test_random_parameters_are_used_or_refused_never_a_crash(originals, tmp_path):
    outcomes = run_worker(["parameters", originals["wall"], "11"], tmp_path)
    assert outcomes["returned"] + outcomes["refused"] == 4 * CASES
    assert outcomes["refused"] > 0


if __name__ == "__main__":
    if sys.argv[1] == "worker":
        work(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]))
    else:
        work_parameters(sys.argv[2], int(sys.argv[3]))
