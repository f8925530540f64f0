#!/usr/bin/env python3
"""Runs the Fortran two-fluid example and recomputes every one of its cells with `gkt table`.

Usage: compare_with_gkt_table.py EXAMPLE GKT

The example prints, per cell, the state (x_1, x_2, phi, n, T), the binary's reduced coefficients
(gkt_binary_table_evaluate_reduced) and its physical ones (gkt_binary_table_evaluate), and writes
the `gkt table` scene of the same binary. For every cell this script runs
    gkt table SCENE --set fraction_1=x_1 --set fraction_2=x_2 --set packing_fraction=phi
and checks, with the tolerances stated below:
  1. reduced: |table - gkt table| <= TABLE_TOLERANCE * max(1, |gkt table|), where
     TABLE_TOLERANCE = 5 x the interpolation error the table measured between its nodes (the
     example's table is an interpolant; gkt table solves each state directly);
  2. physical: the example's physical values against gkt table's reduced ones times the reference
     values of docs/conventions.md (eta0, kappa0, D0, nu0 of m-bar, sigma-bar at n, T, written
     out here), same tolerance;
  3. units: the example's physical values against its own reduced ones times the same reference
     values, to UNIT_TOLERANCE = 1e-12 relative.
Exit status 0 if every check holds, 1 otherwise (one line per failure).
"""

import csv
import io
import json
import math
import os
import subprocess
import sys
import tempfile

UNIT_TOLERANCE = 1e-12
REDUCED = ["shear_viscosity", "thermal_conductivity", "cooling_rate", "temperature_ratio_1", "temperature_ratio_2",
           "mutual_diffusion_1_1", "mutual_diffusion_1_2", "mutual_diffusion_2_1", "mutual_diffusion_2_2",
           "thermal_diffusion_1", "thermal_diffusion_2", "dufour_1", "dufour_2", "pressure", "bulk_viscosity",
           "cooling_rate_first_order"]


def species_of(scene_path):
    """Returns [(mass, diameter)] of the two species in the scene the example wrote."""
    out, current = [], None
    with open(scene_path, encoding="utf-8") as f:
        for line in f:
            key = line.split("=")[0].strip()
            if line.startswith("[[species]]"):
                current = {}
                out.append(current)
            elif current is not None and key in ("mass", "diameter"):
                current[key] = float(line.split("=")[1])
    return [(s["mass"], s["diameter"]) for s in out]


def reference_factors(species, x1, n, t):
    """Returns {physical column: (reduced column, factor)}: physical = reduced x factor, with the
    reference values of the 3D gas of m-bar, sigma-bar at n, T (docs/conventions.md)."""
    x = (x1, 1 - x1)
    mbar = sum(xi * s[0] for xi, s in zip(x, species))
    sbar = sum(xi * s[1] for xi, s in zip(x, species))
    eta0 = 5 / (16 * sbar**2) * math.sqrt(mbar * t / math.pi)
    kappa0 = 15 / 4 * eta0 / mbar
    d0 = 3 / (8 * n * sbar**2) * math.sqrt(t / (math.pi * mbar))
    out = {"eta": ("shear_viscosity", eta0), "lambda": ("thermal_conductivity", kappa0),
           "zeta": ("cooling_rate", n * t / eta0), "p": ("pressure", n * t), "bulk": ("bulk_viscosity", eta0)}
    for i in (1, 2):
        for j in (1, 2):
            out[f"D_{i}{j}"] = (f"mutual_diffusion_{i}_{j}", n * d0)
        out[f"D_T_{i}"] = (f"thermal_diffusion_{i}", d0)
        out[f"D_dufour_{i}"] = (f"dufour_{i}", kappa0 / t)
    return out


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    example, gkt = argv[1], argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as work:
        scene = os.path.join(work, "binary.toml")
        text = subprocess.run([example, scene], check=True, capture_output=True, text=True).stdout
        comments = [line for line in text.splitlines() if line.startswith("#")]
        interpolation_error = float(comments[0].split()[-1])
        tolerance = 5 * interpolation_error
        rows = list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))
        species = species_of(scene)
        worst = 0.0
        for row in rows:
            cell = row["cell"]
            value = {k: float(v) for k, v in row.items() if k != "cell"}
            sets = [f"fraction_1={row['fraction_1'].strip()}", f"fraction_2={row['fraction_2'].strip()}",
                    f"packing_fraction={row['packing_fraction'].strip()}",
                    "coefficients=[" + ", ".join(f'"{c}"' for c in REDUCED) + "]"]
            command = [gkt, "table", scene, "--format", "json"]
            for s in sets:
                command += ["--set", s]
            result = subprocess.run(command, capture_output=True, text=True)
            if result.returncode != 0:
                failures.append(f"cell {cell}: gkt table failed: {result.stderr.strip()}")
                continue
            reference = json.loads(result.stdout)["rows"][0]
            n, t, x1 = value["number_density"], value["temperature"], value["fraction_1"]
            for c in REDUCED:
                difference = abs(value[c] - reference[c]) / max(1.0, abs(reference[c]))
                worst = max(worst, difference)
                if difference > tolerance:
                    failures.append(f"cell {cell}: {c} = {value[c]!r} from the table, {reference[c]!r} from gkt table "
                                    f"(relative difference {difference:.3g} > {tolerance:.3g})")
            for c, (reduced, factor) in reference_factors(species, x1, n, t).items():
                from_gkt, from_own = reference[reduced] * factor, value[reduced] * factor
                if abs(value[c] - from_gkt) > tolerance * max(1.0, abs(reference[reduced])) * factor:
                    failures.append(f"cell {cell}: physical {c} = {value[c]!r}, gkt table x reference {from_gkt!r}")
                if abs(value[c] - from_own) > UNIT_TOLERANCE * max(abs(from_own), 1e-300):
                    failures.append(f"cell {cell}: physical {c} = {value[c]!r}, its own reduced x reference {from_own!r}")
    for f in failures:
        print("compare_with_gkt_table: " + f, file=sys.stderr)
    print(f"compare_with_gkt_table: {len(rows)} cells, largest relative difference from gkt table {worst:.3g} "
          f"(tolerance {tolerance:.3g} = 5 x interpolation error {interpolation_error:.3g}); units to "
          f"{UNIT_TOLERANCE:g}: {'ok' if not failures else f'{len(failures)} failure(s)'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
