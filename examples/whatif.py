#!/usr/bin/env python3
"""What-if with the Python module: three ileal-pouch shapes of the same 300 ml, filled to
capacity on the same wall law; prints Pdet at capacity and the compliance of each.
Usage: PYTHONPATH=build/python python3 examples/whatif.py [BIN_DIR]   (units: ml, cmH2O)"""
import os
import subprocess
import sys
import tempfile

import vesica

bin_dir = sys.argv[1] if len(sys.argv) > 1 else "build/bin"
wall_law = {"material": "neo-hookean", "mu_kpa": 1}  # the thesis's ileum: mu 1 kPa, K = 1000 mu
protocol = {"capacity_ml": 300, "fill_rate_ml_min": 50, "no_void": True}
with tempfile.TemporaryDirectory() as work:
    for elongation in (1.0, 1.5, 2.5):  # left-right length ratio of the pouch
        surface = os.path.join(work, f"pouch-{elongation}.vtp")
        subprocess.run([os.path.join(bin_dir, "vesica-surface"), "-o", surface, "--shape", "pouch",
                        "--volume-ml", "300", "--elongation", str(elongation), "--edge-mm", "6"],
                       check=True, capture_output=True)
        wall = vesica.load_wall(surface, {"residual_ml": 50})
        s = vesica.run_cystometry(wall, wall_law, protocol)["summary"]
        print(f"elongation {elongation}: Pdet at capacity {s['pdet_at_capacity_cmh2o']:.2f} cmH2O,"
              f" compliance {s.get('compliance_ml_per_cmh2o', float('nan')):.1f} ml/cmH2O")
