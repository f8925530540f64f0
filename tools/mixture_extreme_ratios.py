#!/usr/bin/env python3
"""Map the Sonine-order convergence of every binary-mixture Navier–Stokes coefficient over extreme
mass and size ratios (docs/theory.md §17.12). Runs `gkt table` (model "mixture", 3D, x1 = 0.5,
species 1 of unit mass and diameter) at orders 1..N_MAX for each (m2/m1, σ2/σ1, φ, α) and classifies
each coefficient:

  C  converged: |v4 − v3| ≤ 1e-3 |v4| (1e-3 relative at order ≤ 4)
  S  slowly converging: not C, but the steps |v_k − v_{k−1}|, k = 4 … N_MAX, shrink monotonically
  O  oscillating / not converging: neither (steps alternate in sign without shrinking)
  0  identically zero (|v| < 1e-10 at every order: D^T, D^p of identical species); - not defined

Each row also lists T2/T1 of the HCS and D_12* at orders 1..N_MAX.

Usage: tools/mixture_extreme_ratios.py [path/to/gkt] > map.txt   (≈ 5 min; run with nice)
       tools/mixture_extreme_ratios.py --summary map.txt   (the grids of docs/theory.md §17.12: per
       (φ, α) and state the worst class of the mass-flux group D_ij, D^p, D^T / the heat group λ, D'' /
       η / the Enskog scalars η_b, ζ_U)
"""
import csv
import io
import subprocess
import sys

GKT = sys.argv[1] if len(sys.argv) > 1 else "build/bin/gkt"
N_MAX = 6
MASS_RATIOS = ["0.001", "0.01", "0.1", "1", "10", "100", "1000"]
SIZE_RATIOS = ["0.1", "1", "10"]
PACKINGS = ["0", "0.3"]
ALPHAS = ["0.9", "0.5"]
COEFFICIENTS = [
    ("D11", "mutual_diffusion_1_1"), ("D12", "mutual_diffusion_1_2"),
    ("D21", "mutual_diffusion_2_1"), ("D22", "mutual_diffusion_2_2"),
    ("Dp1", "pressure_diffusion_1"), ("DT1", "thermal_diffusion_1"),
    ("lam", "thermal_conductivity"), ("Dq1", "dufour_1"), ("Dq2", "dufour_2"),
    ("eta", "shear_viscosity"), ("etab", "bulk_viscosity"), ("zU", "cooling_rate_first_order"),
]
SCENE = """model = "mixture"
dimension = 3
alpha = {alpha}
{packing}order = 1

[[species]]
name = "one"
mass = 1
diameter = 1
fraction = 0.5

[[species]]
name = "two"
mass = {mass}
diameter = {size}
fraction = 0.5
"""


def classify(values):
    """Returns C, S or O for the orders 1..N_MAX of one coefficient (see the module doc)."""
    steps = [values[k] - values[k - 1] for k in range(1, len(values))]
    scale = max(abs(v) for v in values)
    if scale == 0.0 or abs(steps[2]) <= 1e-3 * abs(values[3]) or abs(steps[2]) <= 1e-13 * scale:
        return "C"
    tail = [abs(s) for s in steps[2:]]
    if all(tail[k + 1] < tail[k] for k in range(len(tail) - 1)):
        return "S"
    return "O"


def run(mass, size, packing, alpha):
    """Returns {column: [v_1 … v_N_MAX]} from one `gkt table` call."""
    text = SCENE.format(alpha=alpha, mass=mass, size=size,
                        packing="" if packing == "0" else f"packing_fraction = {packing}\n")
    orders = "[" + ", ".join(str(n) for n in range(1, N_MAX + 1)) + "]"
    with open("/tmp/gkt_extreme_scene.toml", "w", encoding="utf-8") as scene:
        scene.write(text)
    out = subprocess.run([GKT, "table", "/tmp/gkt_extreme_scene.toml", "--set", f"order={orders}"],
                         capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def main():
    print("# m2/m1 s2/s1 phi alpha | " + " ".join(short for short, _ in COEFFICIENTS) + " | T2/T1 | D12 at orders 1..6")
    for packing in PACKINGS:
        for alpha in ALPHAS:
            for size in SIZE_RATIOS:
                for mass in MASS_RATIOS:
                    table = run(mass, size, packing, alpha)
                    cells = []
                    for short, column in COEFFICIENTS:
                        if column not in table or all(v == 0.0 for v in table[column]):
                            cells.append("-")
                        elif all(abs(v) < 1e-10 for v in table[column]):
                            cells.append("0")
                        else:
                            cells.append(classify(table[column]))
                    worst = table["mutual_diffusion_1_2"]
                    print(f"{mass:>6} {size:>4} {packing:>3} {alpha:>3} | " + " ".join(
                        f"{c:>{len(s)}}" for c, (s, _) in zip(cells, COEFFICIENTS)) +
                        f" | {table['temperature_ratio_2'][0] / table['temperature_ratio_1'][0]:7.3g} | " + " ".join(f"{v:.4g}" for v in worst), flush=True)


GROUPS = [range(0, 6), range(6, 9), range(9, 10), range(10, 12)]


def summary(path):
    """Prints, per (φ, α), a size × mass grid of the worst class (O > S > C) per coefficient group."""
    rank = {"O": 3, "S": 2, "C": 1, "0": 0, "-": 0}
    grids = {}
    with open(path, encoding="utf-8") as lines:
        for line in lines:
            if line.startswith("#"):
                continue
            head, classes = line.split("|")[:2]
            mass, size, packing, alpha = head.split()
            cells = classes.split()
            worst = "".join(max((cells[k] for k in g), key=lambda c: rank[c]) for g in GROUPS)
            grids.setdefault((packing, alpha), {})[(size, mass)] = worst.replace("0", "-")
    for (packing, alpha), grid in grids.items():
        print(f"phi = {packing}, alpha = {alpha}   (mass flux / heat / eta / Enskog scalars)")
        print("s2/s1 \\ m2/m1 " + " ".join(f"{m:>6}" for m in MASS_RATIOS))
        for size in SIZE_RATIOS:
            print(f"{size:>14} " + " ".join(f"{grid[(size, m)]:>6}" for m in MASS_RATIOS))
        print()


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--summary":
        summary(sys.argv[2])
    else:
        main()
