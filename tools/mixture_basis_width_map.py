#!/usr/bin/env python3
"""Count, per binary-mixture state, the Navier–Stokes coefficients that converge with the standard and with
the automatic vector-basis width (`basis_width = "auto"`, docs/theory.md §17.13, (17.30)). Dilute, 3D,
x1 = 0.5, species 1 of unit mass and diameter; m2/m1 = 1e-3 … 1e3, σ2/σ1 = 0.1, 1, 10, α = 0.5, 0.9; orders
1..12 from one `gkt table` call per state and basis. A coefficient counts as converged when its last two
steps (orders 10→11, 11→12) are both ≤ 1e-3 of its order-12 value (the count of theory.md §17.12–17.13).
Ten coefficients: D_11, D_12, D_21, D_22, D^p_1, D^T_1, λ, D''_1, D''_2, η.

Usage: nice tools/mixture_basis_width_map.py [path/to/gkt]   (≈ 2 CPU minutes; one line per state:
       α, m2/m1, σ2/σ1, then the count and the per-coefficient mask (+ converged) of each basis)
"""
import csv
import io
import subprocess
import sys
import tempfile

GKT = sys.argv[1] if len(sys.argv) > 1 else "build/bin/gkt"
N_MAX = 12
MASS_RATIOS = ["0.001", "0.01", "0.1", "1", "10", "100", "1000"]
SIZE_RATIOS = ["0.1", "1", "10"]
ALPHAS = ["0.5", "0.9"]
COLUMNS = ["mutual_diffusion_1_1", "mutual_diffusion_1_2", "mutual_diffusion_2_1", "mutual_diffusion_2_2",
           "pressure_diffusion_1", "thermal_diffusion_1", "thermal_conductivity", "dufour_1", "dufour_2",
           "shear_viscosity"]
SCENE = """model = "mixture"
dimension = 3
alpha = {alpha}
basis_width = "{basis}"
order = 1
coefficients = [{columns}]

[[species]]
mass = 1
diameter = 1
fraction = 0.5

[[species]]
mass = {mass}
diameter = {size}
fraction = 0.5
"""


def converged(values):
    """Returns True if the last two steps are both within 1e-3 of the last value."""
    last = values[-1]
    return abs(values[-1] - values[-2]) <= 1e-3 * abs(last) and abs(values[-2] - values[-3]) <= 1e-3 * abs(last)


def run(alpha, mass, size, basis):
    """Returns (count, mask) of one state in one basis."""
    text = SCENE.format(alpha=alpha, mass=mass, size=size, basis=basis,
                        columns=", ".join(f'"{c}"' for c in COLUMNS))
    with tempfile.NamedTemporaryFile("w", suffix=".toml", encoding="utf-8") as scene:
        scene.write(text)
        scene.flush()
        orders = "[" + ", ".join(str(n) for n in range(1, N_MAX + 1)) + "]"
        out = subprocess.run([GKT, "table", scene.name, "--set", f"order={orders}"],
                             capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    mask = "".join("+" if converged([float(r[c]) for r in rows]) else "." for c in COLUMNS)
    return mask.count("+"), mask


def main():
    print("# alpha m2/m1 s2/s1 | standard count mask | auto count mask")
    for alpha in ALPHAS:
        for size in SIZE_RATIOS:
            for mass in MASS_RATIOS:
                s, a = run(alpha, mass, size, "standard"), run(alpha, mass, size, "auto")
                print(f"{alpha:>3} {mass:>6} {size:>4} | {s[0]:2d} {s[1]} | {a[0]:2d} {a[1]}", flush=True)


if __name__ == "__main__":
    main()
