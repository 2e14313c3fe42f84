"""vesica-simulate --export-feb writes an FEBio 4 input that a real XML parser reads, in the
element and material schema of febio_spec 4.0, whose nodes and elements are the wall's
(round trip against the surface file, read with VTK), whose shells carry vesica's
thickness, whose held nodes are the outlet cap and whose pressure curve ends at the
protocol's last pressure. Run by ctest (test_febio_export) with Debian's python3."""
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

BIN = os.environ.get("VESICA_BIN_DIR", "build/bin")
PA_PER_CMH2O = 98.0665
# febio_spec 4.0: the sections in their order, the parameters of each law used.
SECTIONS = ["Module", "Control", "Material", "Mesh", "MeshDomains", "MeshData", "Boundary",
            "Loads", "LoadData", "Output"]
LAW_PARAMETERS = {
    "Mooney-Rivlin": {"c1", "c2", "k"},
    "Holzapfel-Gasser-Ogden": {"c", "k1", "k2", "kappa", "gamma", "k"},
}


def run(*args):
    result = subprocess.run([os.path.join(BIN, args[0]), *args[1:]], capture_output=True,
                            text=True)
    if result.returncode != 0:
        raise AssertionError(f"{args[0]} failed: {result.stdout}{result.stderr}")


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
    renumbered = [[order[int(n)] for n in c] for c in cells]
    return points[sorted(order, key=order.get)], renumbered, region


def numbers(text):
    return [float(v) for v in text.split(",")]


class FebioExport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vesica-febio-")
        cls.surface = os.path.join(cls.dir, "sphere.vtp")
        run("vesica-surface", "-o", cls.surface, "--shape", "sphere", "--volume-ml", "113.1",
            "--edge-mm", "8", "--outlet", "auto")

    def export(self, name, *options):
        feb = os.path.join(self.dir, name + ".feb")
        run("vesica-simulate", self.surface, "-o", os.path.join(self.dir, name), "--export-feb",
            feb, "--thickness-mm", "2.5", *options)
        return ET.parse(feb).getroot()

    def test_pressure_steps_round_trip_the_wall_in_febio_4_shells(self):
        root = self.export("log", "--protocol", "pressure-steps", "--max-pressure-cmh2o", "2",
                           "--steps", "4", "--k-kpa", "10", "--beta-vol", "0")
        self.assertEqual(root.tag, "febio_spec")
        self.assertEqual(root.get("version"), "4.0")
        self.assertEqual([c.tag for c in root], SECTIONS)

        points, cells, region = read_surface(self.surface)
        nodes = root.find("Mesh/Nodes")
        self.assertEqual(len(nodes), len(points))
        for i, node in enumerate(nodes):
            self.assertEqual(int(node.get("id")), i + 1)
            for got, want in zip(numbers(node.text), points[i]):
                self.assertAlmostEqual(got * 1e3, want, delta=1e-9 * max(1.0, abs(want)))
        elements = root.find("Mesh/Elements")
        self.assertEqual(elements.get("type"), "tri3")
        self.assertEqual(len(elements), len(cells))
        for e, elem in enumerate(elements):
            self.assertEqual([int(v) - 1 for v in elem.text.split(",")], cells[e])
        # The cavity's facets are the elements reversed (FEBio's pressure pushes against
        # the facet normal; the wall's triangles face outwards).
        for elem, facet in zip(elements, root.find("Mesh/Surface[@name='cavity']")):
            a, b, c = elem.text.split(",")
            self.assertEqual(facet.text.split(","), [a, c, b])

        domain = root.find("MeshDomains/ShellDomain")
        self.assertEqual(domain.get("name"), elements.get("name"))
        material = root.find("Material/material")
        self.assertEqual(domain.get("mat"), material.get("name"))
        self.assertEqual(material.get("type"), "Mooney-Rivlin")
        self.assertEqual({p.tag for p in material}, LAW_PARAMETERS["Mooney-Rivlin"])
        self.assertAlmostEqual(float(material.find("c1").text), 2500.0)  # mu / 2 (Pa)
        self.assertAlmostEqual(float(material.find("k").text), 10000.0)
        # beta_vol 0 is FEBio's own volumetric law: no comment about it.
        self.assertNotIn("Ogden volumetric", ET.tostring(root.find("Material"), "unicode"))

        thickness = root.find("MeshData/ElementData[@type='shell thickness']")
        self.assertEqual(thickness.get("elem_set"), elements.get("name"))
        self.assertEqual(len(thickness), len(cells))
        for e in thickness:
            self.assertEqual(numbers(e.text), [0.0025] * 3)

        outlet_nodes = sorted({int(n) + 1 for c, r in zip(cells, region) if r == 2 for n in c})
        held = root.find("Mesh/NodeSet[@name='held_xyz']")
        self.assertEqual(sorted(int(v) for v in held.text.split(",")), outlet_nodes)
        bc = root.find("Boundary/bc[@node_set='held_xyz']")
        self.assertEqual(bc.get("type"), "zero displacement")
        self.assertEqual([bc.find(d).text for d in ("x_dof", "y_dof", "z_dof")], ["1"] * 3)

        load = root.find("Loads/surface_load")
        self.assertEqual((load.get("type"), load.get("surface")), ("pressure", "cavity"))
        curve = root.find(f"LoadData/load_controller[@id='{load.find('pressure').get('lc')}']")
        last = numbers(curve.findall("points/pt")[-1].text)
        self.assertAlmostEqual(last[1] * float(load.find("pressure").text), 2 * PA_PER_CMH2O)
        self.assertEqual(int(root.find("Control/time_steps").text), 4)

    def test_what_febio_lacks_is_said_in_comments(self):
        path = os.path.join(self.dir, "maxwell.feb")
        self.export("maxwell", "--protocol", "volume-steps", "--max-stretch", "1.05",
                    "--steps", "2", "--material", "maxwell", "--beta", "0.2", "--tau-s", "3")
        root = ET.parse(path).getroot()
        material = root.find("Material/material")
        self.assertEqual(material.get("type"), "uncoupled viscoelastic")
        self.assertEqual((float(material.find("g1").text), float(material.find("t1").text)),
                         (0.2, 3.0))
        self.assertEqual(material.find("elastic").get("type"), "Mooney-Rivlin")
        text = open(path, encoding="iso-8859-1").read()
        self.assertIn("Ogden volumetric term", text)  # beta_vol 9 has no FEBio law
        self.assertIn("tension field", text)
        self.assertIn("no volume-controlled cavity", text)


if __name__ == "__main__":
    sys.exit(unittest.main())
