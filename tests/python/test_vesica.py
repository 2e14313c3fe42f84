"""The Python module `vesica` against vesica-simulate on the same wall: the same
cystometry gives the same Pdet at capacity to 1e-9 relative, the history comes back as
numpy columns and the readers return what the files hold. Run by ctest (test_python) with
Debian's python3 and pytest; VESICA_BIN_DIR names the executables and PYTHONPATH the
module."""
import json
import os
import subprocess

import numpy as np
import pytest

import vesica

BIN = os.environ.get("VESICA_BIN_DIR", "build/bin")
MATERIAL = {"name": "neo-hookean", "mu": 5e3, "K_per_mu": 1000.0}  # --material neo-hookean --mu-kpa 5
PROTOCOL = {"start_ml": 50, "capacity_ml": 120, "fill_rate_ml_min": 50, "no_void": True}


def tool(*args):
    result = subprocess.run([os.path.join(BIN, args[0]), *map(str, args[1:])],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout


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
    with pytest.raises(vesica.Error, match="capacity"):
        vesica.run_cystometry(wall, MATERIAL, {"capacity_mll": 100})
    with pytest.raises(vesica.Error, match="mu"):
        vesica.run_cystometry(wall, {"name": "neo-hookean", "mu": -1.0}, PROTOCOL)


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
    with pytest.raises(vesica.Error, match="max_simulation"):
        vesica.calibrate(wall, recording, "mu", {"max_simulation": 8})
