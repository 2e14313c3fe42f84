"""vesica-simulate --export-feb writes what ran as an FEBio 4 input (febio_spec 4.0) that a
real XML parser reads: the named material's own values as the documented defaults give
them (docs/physics.md section 2.7), each element's fiber directions, the wall's nodes as
FEBio's outer shell face (half the thickness out from vesica's mid-surface), its thickness
and held cap, the pressures vesica computed as the load curve, and FEBio's solver settings;
what FEBio cannot express is an error naming the parameter, or with --febio-approximate a
warning and a comment. Whether FEBio then gives vesica's curve is FebioCrossCheckTest.py.
Run by ctest (test_febio_export) with Debian's python3."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

BIN = os.environ.get("VESICA_BIN_DIR", "build/bin")
PA_PER_CMH2O = 98.0665
# febio_spec 4.0: the sections in their order.
SECTIONS = ["Module", "Control", "Material", "Mesh", "MeshDomains", "MeshData", "Boundary",
            "Loads", "LoadData", "Output"]


def simulate(*args):
    return subprocess.run([os.path.join(BIN, "vesica-simulate"), *args], capture_output=True,
                          text=True)


def numbers(text):
    return [float(v) for v in text.split(",")]


def read_surface(path):
    """Points (mm), triangles and regions of a .vtp, its points numbered as vesica-simulate
    numbers a wall: in the order the triangles first use them."""
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    points = vtk_to_numpy(poly.GetPoints().GetData())
    cells = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    region = vtk_to_numpy(poly.GetCellData().GetArray("region"))
    order = {}
    for n in cells.flatten():
        order.setdefault(int(n), len(order))
    renumbered = np.array([[order[int(n)] for n in c] for c in cells])
    return points[sorted(order, key=order.get)], renumbered, region


def value(material, path):
    return float(material.find(path).text)


class FebioExport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vesica-febio-")
        cls.surface = os.path.join(cls.dir, "sphere.vtp")
        result = subprocess.run(
            [os.path.join(BIN, "vesica-surface"), "-o", cls.surface, "--shape", "sphere",
             "--volume-ml", "113.1", "--edge-mm", "8", "--outlet", "auto"],
            capture_output=True, text=True)
        assert result.returncode == 0, result.stderr

    def export(self, name, *options):
        feb = os.path.join(self.dir, name + ".feb")
        result = simulate(self.surface, "-o", os.path.join(self.dir, name), "--export-feb", feb,
                          "--thickness-mm", "2.5", *options)
        self.assertEqual(result.returncode, 0, result.stderr)
        return ET.parse(feb).getroot(), result

    def refused(self, *options):
        result = simulate(self.surface, "-o", os.path.join(self.dir, "refused"), "--export-feb",
                          os.path.join(self.dir, "refused.feb"), *options)
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "refused.feb")))
        return result.stderr

    def test_the_wall_round_trips_as_febio_shells_on_vesicas_mid_surface(self):
        root, _ = self.export("wall", "--protocol", "pressure-steps", "--material",
                              "neo-hookean", "--beta-vol", "0", "--max-pressure-cmh2o", "2",
                              "--steps", "4")
        self.assertEqual((root.tag, root.get("version")), ("febio_spec", "4.0"))
        self.assertEqual([c.tag for c in root], SECTIONS)
        points, cells, region = read_surface(self.surface)
        nodes = np.array([numbers(n.text) for n in root.find("Mesh/Nodes")]) * 1e3  # mm
        self.assertEqual(len(nodes), len(points))
        # Each node half the thickness (1.25 mm) out from vesica's, along the sphere's radius
        # (FEBio's nodes are its shell's outer face).
        offset = nodes - points
        centre = points.mean(axis=0)
        radial = (points - centre) / np.linalg.norm(points - centre, axis=1)[:, None]
        np.testing.assert_allclose(np.einsum("ij,ij->i", offset, radial), 1.25, rtol=0.02)
        np.testing.assert_allclose(np.linalg.norm(offset - np.einsum(
            "ij,ij->i", offset, radial)[:, None] * radial, axis=1), 0, atol=0.05)
        elements = root.find("Mesh/Elements")
        self.assertEqual(elements.get("type"), "tri3")
        self.assertEqual([[int(v) - 1 for v in e.text.split(",")] for e in elements],
                         cells.tolist())
        # The cavity's facets are the elements' own: the pressure on the shell's bottom
        # (inner) face pushes along their outward normal.
        facets = root.find("Mesh/Surface[@name='cavity']")
        self.assertEqual([f.text for f in facets], [e.text for e in elements])
        load = root.find("Loads/surface_load")
        self.assertEqual((load.get("type"), load.get("surface"), load.find("shell_bottom").text),
                         ("pressure", "cavity", "1"))
        domain = root.find("MeshDomains/ShellDomain")
        self.assertEqual((domain.get("name"), domain.get("type")), ("wall", "three-field-shell"))
        thickness = root.find("MeshData/ElementData[@type='shell thickness']")
        self.assertEqual(len(thickness), len(cells))
        for e in thickness:
            self.assertEqual(numbers(e.text), [0.0025] * 3)
        outlet_nodes = sorted({int(n) + 1 for c, r in zip(cells, region) if r == 2 for n in c})
        held = root.find("Mesh/NodeSet[@name='held_xyz']")
        self.assertEqual(sorted(int(v) for v in held.text.split(",")), outlet_nodes)
        bc = root.find("Boundary/bc[@node_set='held_xyz']")
        self.assertEqual(bc.get("type"), "zero displacement")
        self.assertEqual([bc.find(d).text for d in ("x_dof", "y_dof", "z_dof")], ["1"] * 3)

    def test_the_load_curve_is_vesicas_pressures_and_febio_stops_at_each(self):
        root, _ = self.export("curve", "--protocol", "pressure-steps", "--material",
                              "neo-hookean", "--beta-vol", "0", "--max-pressure-cmh2o", "2",
                              "--steps", "4")
        with open(os.path.join(self.dir, "curve", "pressure_stretch.csv")) as f:
            vesica = [float(r["pressure_pa"]) for r in csv.DictReader(f)]
        load = root.find("Loads/surface_load/pressure")
        curve = root.find(f"LoadData/load_controller[@id='{load.get('lc')}']")
        points = [numbers(p.text) for p in curve.find("points")]
        np.testing.assert_allclose([p[1] * float(load.text) for p in points], vesica,
                                   rtol=1e-11)
        self.assertAlmostEqual(points[-1][1], 2 * PA_PER_CMH2O)
        control = root.find("Control")
        must = root.find(f"LoadData/load_controller"
                         f"[@id='{control.find('time_stepper/dtmax').get('lc')}']")
        self.assertEqual([numbers(p.text)[0] for p in must.find("points")],
                         [p[0] for p in points])
        self.assertEqual(must.find("interpolate").text, "STEP")
        self.assertAlmostEqual(int(control.find("time_steps").text) *
                               float(control.find("step_size").text), points[-1][0])
        solver = control.find("solver")
        self.assertEqual(solver.get("type"), "solid")  # FEBio 4.11 refuses a file without
        self.assertEqual(solver.find("optimize_bw").text, "1")  # FEBio's own renumbering
        self.assertEqual(solver.find("qn_method").get("type"), "full Newton")
        self.assertEqual(control.find("time_stepper").get("type"), "default")

    def test_volume_steps_past_the_limit_point_load_febio_up_to_the_highest_pressure(self):
        root, _ = self.export("volume", "--protocol", "volume-steps", "--material",
                              "neo-hookean", "--beta-vol", "0", "--max-stretch", "1.8",
                              "--steps", "8")
        with open(os.path.join(self.dir, "volume", "pressure_stretch.csv")) as f:
            vesica = [float(r["pressure_pa"]) for r in csv.DictReader(f)]
        peak = vesica.index(max(vesica))
        self.assertLess(peak, len(vesica) - 1)  # the thin sphere's limit at a stretch of 1.38
        points = [numbers(p.text) for p in root.find("LoadData/load_controller[@id='1']/points")]
        np.testing.assert_allclose([p[1] for p in points], vesica[:peak + 1], rtol=1e-11)
        with open(os.path.join(self.dir, "volume.feb"), encoding="iso-8859-1") as f:
            self.assertIn("up to the highest", f.read())

    def test_the_neo_hookean_matrix_is_febios_mooney_rivlin_with_the_same_moduli(self):
        root, _ = self.export("nh", "--protocol", "pressure-steps", "--material", "neo-hookean",
                              "--beta-vol", "0", "--mu-kpa", "4", "--k-kpa", "300", "--steps",
                              "2")
        material = root.find("Material/material")
        self.assertEqual(material.get("type"), "Mooney-Rivlin")
        self.assertEqual([value(material, p) for p in ("c1", "c2", "k")],
                         [2000.0, 0.0, 300000.0])  # c1 = mu/2 (Pa)

    def test_the_default_bladder_exports_its_own_values(self):
        # docs/physics.md 2.7: mu 0.6 kPa, K = 1000 mu, k1 125 Pa, k2 0.02, one branch
        # beta 0.2; the verification's steps respond instantaneously, the passive stress
        # times 1 + 0.2, and FEBio's uncoupled fibers take K = 1e4 mu.
        message = self.refused("--protocol", "pressure-steps", "--beta-vol", "0")
        self.assertIn("--export-feb: k1 = 125 Pa", message)
        self.assertIn("--febio-approximate", message)
        root, result = self.export("bladder", "--protocol", "pressure-steps", "--beta-vol", "0",
                                   "--steps", "2", "--febio-approximate")
        self.assertIn("--export-feb: k1 = 125 Pa", result.stderr)
        mixture = root.find("Material/material")
        self.assertEqual(mixture.get("type"), "uncoupled solid mixture")
        self.assertAlmostEqual(value(mixture, "k"), 1.2 * 1e4 * 600.0)
        matrix, *fibers = mixture.findall("solid")
        self.assertEqual(matrix.get("type"), "Mooney-Rivlin")
        self.assertAlmostEqual(value(matrix, "c1"), 1.2 * 600.0 / 2)
        self.assertEqual(len(fibers), 2)
        for fiber, name in zip(fibers, ("fiber1", "fiber2")):
            self.assertEqual(fiber.get("type"), "fiber-exp-pow-uncoupled")
            self.assertAlmostEqual(value(fiber, "ksi"), 1.2 * 125.0)
            self.assertAlmostEqual(value(fiber, "alpha"), 0.02)
            self.assertEqual(value(fiber, "beta"), 2.0)
            self.assertEqual((fiber.find("fiber").get("type"), fiber.find("fiber").text),
                             ("map", name))
        # Each element's two directions: unit, in its plane, at right angles.
        _, cells, _ = read_surface(self.surface)
        points = read_surface(self.surface)[0]
        maps = [np.array([numbers(e.text) for e in root.find(
            f"MeshData/ElementData[@name='{name}']")]) for name in ("fiber1", "fiber2")]
        a, b, c = points[cells[:, 0]], points[cells[:, 1]], points[cells[:, 2]]
        normal = np.cross(b - a, c - a)
        normal /= np.linalg.norm(normal, axis=1)[:, None]
        for m in maps:
            np.testing.assert_allclose(np.linalg.norm(m, axis=1), 1.0, atol=1e-12)
            np.testing.assert_allclose(np.einsum("ij,ij->i", m, normal), 0.0, atol=1e-12)
        np.testing.assert_allclose(np.einsum("ij,ij->i", *maps), 0.0, atol=1e-12)

    def test_fibers_without_k1_export_the_10_kpa_vesica_simulates(self):
        root, _ = self.export("fibers", "--protocol", "pressure-steps", "--material", "fibers",
                              "--beta-vol", "0", "--steps", "2", "--febio-approximate")
        fiber = root.find("Material/material/solid[@type='fiber-exp-pow-uncoupled']")
        self.assertEqual((value(fiber, "ksi"), value(fiber, "alpha")), (10000.0, 1.0))

    def test_a_cystometry_exports_its_filling_with_relaxing_branches(self):
        options = ("--material", "maxwell", "--beta", "0.2", "--tau-s", "3", "--beta-vol", "0",
                   "--wall-drag-pa-s-per-m", "0", "--no-void", "--capacity-ml", "120")
        self.assertIn("--export-feb: beta_vol = 9", self.refused(
            "--material", "maxwell", "--no-void", "--capacity-ml", "120"))
        self.assertIn("--export-feb: wall_drag_pa_s_per_m = 1e+04", self.refused(
            "--material", "maxwell", "--beta-vol", "0", "--no-void", "--capacity-ml", "120"))
        root, result = self.export("filling", *options)
        self.assertNotIn("approximated", ET.tostring(root, "unicode"))
        material = root.find("Material/material")
        self.assertEqual(material.get("type"), "uncoupled viscoelastic")
        self.assertEqual((value(material, "g1"), value(material, "t1")), (0.2, 3.0))
        self.assertEqual(material.find("elastic").get("type"), "Mooney-Rivlin")
        with open(os.path.join(self.dir, "filling", "history.csv")) as f:
            rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
        points = [numbers(p.text) for p in root.find("LoadData/load_controller[@id='1']/points")]
        # The settling: a ramp of 1000 relaxation times to the first row's Pdet, then the
        # filling's Pdet at its times.
        settle = 1000 * 3.0
        filling = [p for p in points if p[0] >= settle]
        self.assertEqual(len(filling), len(rows))
        for (t, p), r in zip(filling, rows):
            self.assertAlmostEqual(t - settle, float(r["time_s"]), places=6)
            self.assertAlmostEqual(p / PA_PER_CMH2O, float(r["pdet_cmh2o"]), places=6)
        self.assertEqual(points[0], [0.0, 0.0])


if __name__ == "__main__":
    sys.exit(unittest.main())
