#!/usr/bin/env python3
"""One row of a gkt table from Python: the Navier-Stokes coefficients of dilute inelastic hard
spheres at alpha = 0.8, Sonine order 2, printed as CSV (header and row).

    PYTHONPATH=build/python python3 examples/python/table_row.py [GKT]

With the path of the gkt program (as CTest passes it, examples/CMakeLists.txt) the script also runs
    gkt table - on the same scene
and exits 1 unless every column has the same name, in the same order, and the same double.
"""

import csv
import io
import os
import subprocess
import sys
import tempfile

import gkt  # build with -DGKT_BUILD_PYTHON=ON; the module is build/python/gkt*.so

SCENE = """\
model = "smooth-inelastic"
dimension = 3
alpha = 0.8
order = 2
coefficients = ["cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"]
"""

columns = gkt.table(SCENE)  # {column: NumPy array}, the CLI's canonical names
names = list(columns)
row = [repr(columns[name][0].item()) for name in names]  # shortest round-trip decimals, as gkt table
print(",".join(names))
print(",".join(row))

if len(sys.argv) > 1:
    with tempfile.TemporaryDirectory() as scratch:
        path = os.path.join(scratch, "scene.toml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(SCENE)
        done = subprocess.run([sys.argv[1], "table", path], capture_output=True, text=True, check=True)
    header, cli_row = list(csv.reader(io.StringIO(done.stdout)))[:2]
    if header != names or [float(c) for c in cli_row] != [float(c) for c in row]:
        print(f"differs from gkt table:\n{done.stdout}", file=sys.stderr)
        sys.exit(1)
    print("equal to gkt table on the same scene")
