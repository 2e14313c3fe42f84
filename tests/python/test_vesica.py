"""The Python module `vesica` against vesica-simulate on the same wall: the same
cystometry gives the same Pdet at capacity to 1e-9 relative, the history comes back as
numpy columns and the readers return what the files hold. Its arguments are taken by
value: no dict is changed, no default is shared, a bad key fails its own call only; every
catalogue key resolves on the model card to the value given (issue 38). Run by ctest
(test_python) with Debian's python3 and pytest; VESICA_BIN_DIR names the executables and
PYTHONPATH the module."""
import copy
import json
import os
import subprocess

import numpy as np
import pytest

import vesica
from vesica_tools import tool

MATERIAL = {"material": "neo-hookean", "mu_kpa": 5}  # --material neo-hookean --mu-kpa 5
PROTOCOL = {"start_ml": 50, "capacity_ml": 120, "fill_rate_ml_min": 50, "no_void": True}


@pytest.fixture(scope="module")
def sphere(tmp_path_factory):
    path = tmp_path_factory.mktemp("python") / "sphere.vtp"
    tool("vesica-surface", "-o", path, "--shape", "sphere", "--volume-ml", 100, "--edge-mm", 8,
         "--outlet", "auto")
    return path


def test_python_cystometry_equals_the_command_line(sphere, tmp_path):
    out = tmp_path / "cli"
    cli = json.loads(tool("vesica-simulate", sphere, "-o", out, "--material", "neo-hookean",
                          "--mu-kpa", 5, "--start-ml", 50,
                          "--capacity-ml", 120, "--fill-rate-ml-min", 50, "--no-void",
                          "--no-series", "--json"))
    wall = vesica.load_wall(str(sphere))
    result = vesica.run_cystometry(wall, MATERIAL, PROTOCOL)
    assert result["completed"], result["failure"]
    py = result["summary"]["pdet_at_capacity_cmh2o"]
    assert py == pytest.approx(cli["pdet_at_capacity_cmh2o"], rel=1e-9)
    assert py > 0.0

    history = result["history"]
    assert isinstance(history["pdet_cmh2o"], np.ndarray)
    assert set(history) == {"time_s", "infused_ml", "volume_ml", "pves_cmh2o", "pabd_cmh2o",
                            "pdet_cmh2o", "flow_ml_s", "voided_ml"}
    np.testing.assert_allclose(history["pdet_cmh2o"],
                               history["pves_cmh2o"] - history["pabd_cmh2o"], atol=1e-9)
    # The same history as the CLI's file, column by column.
    # history.csv opens with comment lines (what voided it); the column names follow them.
    lines = [l for l in (out / "history.csv").read_text().splitlines() if not l.startswith("#")]
    cli_history = np.genfromtxt(lines, delimiter=",", names=True)
    np.testing.assert_allclose(history["volume_ml"], cli_history["volume_ml"], rtol=1e-6)

    # ICS parameters of the CLI's history: its capacity is the protocol's.
    ics = vesica.ics_parameters(str(out / "history.csv"))
    assert ics["capacity_ml"] == pytest.approx(120.0, rel=1e-3)


def test_wall_and_readers_return_the_files_content(sphere):
    surface = vesica.read_surface(str(sphere))
    assert surface["points_mm"].shape[1] == 3 and surface["triangles"].shape[1] == 3
    # A closed triangulated sphere: V - E + F = 2 with E = 3F/2.
    assert len(surface["points_mm"]) - len(surface["triangles"]) / 2 == 2
    wall = vesica.load_wall(str(sphere), {"residual_ml": 40})
    assert wall.volume_ml == pytest.approx(40.0, rel=1e-9)  # scaled to the residual volume
    assert wall.triangle_count == len(surface["triangles"])


def test_bad_parameters_raise_with_the_option_named(sphere):
    wall = vesica.load_wall(str(sphere))
    with pytest.raises(ValueError, match="capacity"):
        vesica.run_cystometry(wall, MATERIAL, {"capacity_mll": 100})
    with pytest.raises(ValueError, match="mu_kpa"):
        vesica.run_cystometry(wall, {"material": "neo-hookean", "mu_kpa": -1.0}, PROTOCOL)
    with pytest.raises(ValueError, match="k1"):
        vesica.run_cystometry(wall, {"material": "neo-hookean", "k1_kpa": 1.0}, PROTOCOL)


def test_no_argument_is_changed(sphere):
    options = {"residual_ml": 40, "posture": "sitting"}
    material = {"material": "bladder", "contractility_kpa": 80}
    protocol = {"capacity_ml": 100, "fill_rate_ml_min": 60, "level": 0}
    before = [copy.deepcopy(d) for d in (options, material, protocol)]
    wall = vesica.load_wall(str(sphere), options)
    vesica.run_cystometry(wall, material, protocol)
    vesica.model_card(wall, material, protocol)
    assert [options, material, protocol] == before
    # A dict changed after the call does not reach the wall either.
    options["residual_ml"] = 90
    card = vesica.model_card(wall)
    assert card["reference"]["residual_ml"] == 40
    assert card["protocol"]["posture"] == "sitting"


def test_a_second_run_without_a_protocol_is_the_first_on_a_fresh_wall(sphere):
    # Earlier, the protocol's keys were written into the wall's (and the shared default
    # dict's) options, so that a later call inherited another call's capacity.
    wall = vesica.load_wall(str(sphere))
    vesica.run_cystometry(wall, MATERIAL, {"capacity_ml": 90, "no_void": True, "level": 0})
    other = vesica.load_wall(str(sphere))
    vesica.run_cystometry(other, MATERIAL, {"capacity_ml": 70, "no_void": True, "level": 0})
    again = vesica.run_cystometry(wall, MATERIAL, {"level": 0})
    fresh = vesica.run_cystometry(vesica.load_wall(str(sphere)), MATERIAL, {"level": 0})
    assert again["model_card"] == fresh["model_card"]
    assert again["model_card"]["protocol"]["capacity_ml"] == 350  # vesica-simulate's default
    np.testing.assert_array_equal(again["history"]["pdet_cmh2o"], fresh["history"]["pdet_cmh2o"])


def test_a_typo_fails_only_its_own_call(sphere):
    wall = vesica.load_wall(str(sphere))
    first = vesica.run_cystometry(wall, MATERIAL, PROTOCOL)
    with pytest.raises(ValueError, match="'capacity'"):
        vesica.run_cystometry(wall, MATERIAL, {"capacity": 350})
    with pytest.raises(ValueError):
        vesica.load_wall(str(sphere), {"residual": 40})
    after = vesica.run_cystometry(wall, MATERIAL, PROTOCOL)
    np.testing.assert_array_equal(first["history"]["pdet_cmh2o"], after["history"]["pdet_cmh2o"])


# Where the model card holds each catalogue parameter (ModelCardJson.h's layout).
CARD_PATH = {
    "mu": ("material", "mu_pa"), "k": ("material", "k_pa"), "k1": ("material", "fibers", "k1_pa"),
    "k2": ("material", "fibers", "k2"), "beta_vol": ("material", "beta_vol"),
    "tone": ("material", "muscle", "tone_pa"),
    "contractility": ("material", "muscle", "contractility_pa"),
    "optimal_stretch": ("material", "muscle", "optimal_stretch"),
    "stretch_width": ("material", "muscle", "stretch_width"),
    "hill_a": ("material", "muscle", "hill_a"), "hill_vmax": ("material", "muscle", "hill_vmax_per_s"),
    "p_open": ("urethra", "p_open_cmh2o"), "p_close": ("urethra", "p_close_cmh2o"),
    "r1": ("urethra", "r1_cmh2o_s_per_ml"), "r2": ("urethra", "r2_cmh2o_s2_per_ml2"),
    "urethra_half_open": ("urethra", "half_open_cmh2o"),
    "urethra_recovery_half": ("urethra", "recovery_half"),
    "straining": ("voiding", "straining_kpa"), "activation_delay": ("voiding", "activation", "delay_s"),
    "activation_onset": ("voiding", "activation", "onset_s"),
    "activation_plateau": ("voiding", "activation", "plateau_s"),
    "activation_fade": ("voiding", "activation", "fade_s"),
}


def card_value(card, entry):
    """The card's value of a catalogue parameter, in SI: the material's are SI on the card,
    the protocol's in the key's own unit."""
    if entry["per_branch"]:
        field = "beta" if entry["name"] == "beta" else "tau_s"
        return [b[field] for b in card["material"]["maxwell_branches"]]
    value = card
    for step in CARD_PATH[entry["name"]]:
        value = value[step]
    return value if CARD_PATH[entry["name"]][0] == "material" else value * entry["si_per_unit"]


def test_every_catalogue_key_resolves_on_the_card_for_each_material(sphere):
    wall = vesica.load_wall(str(sphere))
    catalogue = vesica.parameter_catalogue()
    assert {e["name"] for e in catalogue if not e["per_branch"]} == set(CARD_PATH)
    for material in ("bladder", "neobladder", "neo-hookean", "maxwell", "fibers"):
        default = vesica.model_card(wall, {"material": material})
        for e in catalogue:
            if material not in e["defaults_si"]:
                with pytest.raises(ValueError):
                    vesica.model_card(wall, {"material": material, e["key"]: 0.5})
                continue
            if e["per_branch"]:
                assert card_value(default, e) == pytest.approx(list(e["defaults_si"][material]))
                continue
            d = e["defaults_si"][material][0]
            assert card_value(default, e) == pytest.approx(d, rel=1e-12), (material, e["key"])
            # In range for every entry (p_open above the default p_close), and not the default.
            v = 30.0 if e["name"] == "p_open" else 0.5 if d != 0.5 * e["si_per_unit"] else 0.25
            given = vesica.model_card(wall, {"material": material, e["key"]: v})
            assert card_value(given, e) == pytest.approx(v * e["si_per_unit"], rel=1e-12), \
                (material, e["key"])


def test_python_calibration_equals_the_command_line(sphere, tmp_path):
    # vesica-compare --calibrate and vesica.calibrate on the same wall and recording: the
    # same fitted mu, RMSE and verdict, and the fit carries its interval and baselines.
    mesh = tmp_path / "wall.msh"
    tool("vesica-mesh", sphere, "-o", mesh)
    wall = str(mesh.with_suffix(".vtu"))
    recording = os.path.join(os.path.dirname(__file__), "..", "..", "pipelines", "data",
                             "normal-female-34y.csv")
    cli = json.loads(tool("vesica-compare", "--measured", recording, "--mesh", wall,
                          "--calibrate", "mu", "--max-simulations", 8, "--no-pdf",
                          "-o", tmp_path / "report", "--json"))
    fit = vesica.calibrate(wall, recording, "mu", {"max_simulations": 8})
    mu = fit["parameters"][0]
    assert mu["name"] == "mu"
    assert mu["value"] == pytest.approx(cli["fitted_mu"], rel=1e-12)
    assert fit["rmse_cmh2o"] == pytest.approx(cli["fit_rmse_cmh2o"], rel=1e-12)
    assert fit["status"] == cli["fit_status"]
    assert mu["ci95_low"] <= mu["value"] <= mu["ci95_high"]
    filling = fit["series"][0]
    assert {"rmse", "constant_baseline_rmse", "line_baseline_rmse"} <= set(filling)
    with pytest.raises(ValueError, match="max_simulation"):
        vesica.calibrate(wall, recording, "mu", {"max_simulation": 8})


def run_python(script, timeout_s):
    """`script` in a fresh interpreter (the module's first use is its own), with a limit:
    a deadlock or an abort is this test's failure, not the session's."""
    try:
        result = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True,
                                text=True, timeout=timeout_s, env=dict(os.environ))
    except subprocess.TimeoutExpired:
        pytest.fail(f"no answer within {timeout_s} s (a deadlock)")
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


def test_two_threads_first_reads_finish(sphere):
    # Issue 37: the first array either thread made looked numpy up in a static; the two
    # first read_surface calls then waited for each other forever.
    out = run_python(f"""
import threading, vesica
results = []
def read():
    results.append(len(vesica.read_surface({str(sphere)!r})["triangles"]))
threads = [threading.Thread(target=read, daemon=True) for _ in range(4)]
for t in threads: t.start()
for t in threads: t.join(60)
print(sorted(results))
""", 120)
    triangles = len(vesica.read_surface(str(sphere))["triangles"])
    assert out.strip() == str([triangles] * 4)


def test_concurrent_cystometries_on_one_wall_equal_a_serial_one(sphere):
    # Issue 37: two threads' runs on one wall aborted in the solvers' Fortran runtime. They
    # now take turns: each thread's Pdet is the serial run's, value for value.
    serial = vesica.run_cystometry(vesica.load_wall(str(sphere)), MATERIAL, PROTOCOL)
    out = run_python(f"""
import json, threading, vesica
wall = vesica.load_wall({str(sphere)!r})
results = {{}}
def run(i):
    r = vesica.run_cystometry(wall, {MATERIAL!r}, {PROTOCOL!r})
    results[i] = [r["completed"], list(r["history"]["pdet_cmh2o"])]
threads = [threading.Thread(target=run, args=(i,), daemon=True) for i in range(3)]
for t in threads: t.start()
for t in threads: t.join(300)
print(json.dumps(results))
""", 400)
    results = json.loads(out)
    assert len(results) == 3
    for completed, pdet in results.values():
        assert completed
        np.testing.assert_array_equal(np.array(pdet), serial["history"]["pdet_cmh2o"])
