#!/usr/bin/env python3
"""Plot sticking grains (docs/theory.md §20) as a standalone SVG: ψ(x) of the criteria, N(t) and θ(t)
of a population balance, and its size distribution n_k at a few times. Standard library only.

    S=tables/scenes/aggregation_pair.toml; X='critical_energy={from=0.02, to=8, points=60}'
    build/bin/gkt table $S --set "$X" --set size_j=1 --set 'coefficients=["success_factor"]' --output /tmp/psi3.csv
    build/bin/gkt table $S --set "$X" --set size_j=1 --set dimension=2 --set 'coefficients=["success_factor"]' --output /tmp/psi2.csv
    build/bin/gkt table $S --set "$X" --set size_j=1 --set 'criterion="normal-impact"' --set 'coefficients=["success_factor"]' --output /tmp/psin.csv
    build/bin/gkt evolve tables/scenes/aggregation_evolve.toml --set 'grid="geometric"' --set sizes=100000 --set t_end=100 --set points=40 --output /tmp/agg.csv
    build/bin/gkt evolve tables/scenes/aggregation_evolve.toml --set 'grid="geometric"' --set sizes=100000 --set t_end=100 --set points=4 --set distribution=true --output /tmp/aggdist.csv
    python3 tools/plot_aggregation.py docs/aggregation.svg /tmp/psi3.csv /tmp/psi2.csv /tmp/psin.csv /tmp/agg.csv /tmp/aggdist.csv
"""
import csv
import math
import sys

W, H, PAD = 320, 280, 52
COLOURS = ["#d95f02", "#1b9e77", "#7570b3", "#e7298a"]


def panel(svg, x0, title, xlabel, ylabel, series, xlog, ylog, xr, yr):
    def tx(v):
        v = math.log10(v) if xlog else v
        return x0 + PAD + (v - xr[0]) / (xr[1] - xr[0]) * (W - PAD - 12)

    def ty(v):
        v = math.log10(v) if ylog else v
        return H - PAD + 12 - (v - yr[0]) / (yr[1] - yr[0]) * (H - PAD - 12)

    svg.append(f'<rect x="{x0 + PAD}" y="12" width="{W - PAD - 12}" height="{H - PAD - 12}" fill="none" stroke="#888"/>')
    svg.append(f'<text x="{x0 + W / 2}" y="{H - 14}" text-anchor="middle">{xlabel}</text>')
    svg.append(f'<text x="{x0 + 12}" y="{H / 2}" transform="rotate(-90 {x0 + 12} {H / 2})" text-anchor="middle">{ylabel}</text>')
    svg.append(f'<text x="{x0 + W / 2}" y="10" text-anchor="middle">{title}</text>')
    for k in range(5):
        for axis, lo, hi, log in (("x", *xr, xlog), ("y", *yr, ylog)):
            v = lo + k * (hi - lo) / 4
            label = f"1e{v:g}" if log else f"{v:g}"
            if axis == "x":
                svg.append(f'<text x="{x0 + PAD + k * (W - PAD - 12) / 4}" y="{H - PAD + 26}" text-anchor="middle">{label}</text>')
            else:
                svg.append(f'<text x="{x0 + PAD - 4}" y="{H - PAD + 16 - k * (H - PAD - 12) / 4}" text-anchor="end">{label}</text>')
    for i, (label, points) in enumerate(series):
        def inside(v, r, log):
            return (v > 0 and r[0] <= math.log10(v) <= r[1]) if log else r[0] <= v <= r[1]

        pts = " ".join(f"{tx(x):.1f},{ty(y):.1f}" for x, y in points if inside(x, xr, xlog) and inside(y, yr, ylog))
        svg.append(f'<polyline points="{pts}" fill="none" stroke="{COLOURS[i % 4]}" stroke-width="1.5"/>')
        svg.append(f'<text x="{x0 + PAD + 8}" y="{28 + 14 * i}" fill="{COLOURS[i % 4]}">{label}</text>')


def main(target, psi3, psi2, psin, evolution, distribution):
    def psi(path):
        return [(float(r["critical_energy"]), float(r["success_factor"])) for r in csv.DictReader(open(path))]

    rows = list(csv.DictReader(open(evolution)))
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{3 * W}" height="{H + 10}" font-family="sans-serif" font-size="11">']
    panel(svg, 0, "success factor (two monomers, θ = θ0)", "x = θ*/θ", "ψ",
          [("3D relative speed: 1 − (1+x)e^−x", psi(psi3)), ("2D relative speed", psi(psi2)), ("normal impact: 1 − e^−x", psi(psin))],
          False, False, (0, 8), (0, 1))
    panel(svg, W, "population balance (3D, α = 0.9, θ*11 = θ0)", "t / t0", "",
          [("N / N(0)", [(float(r["time"]), float(r["number_density"])) for r in rows]),
           ("θ / θ0", [(float(r["time"]), float(r["temperature"])) for r in rows]),
           ("ψ (collision average)", [(float(r["time"]), float(r["success_factor"])) for r in rows])],
          True, True, (-2, 2), (-3, 1))
    by_time = {}
    for r in csv.DictReader(open(distribution)):
        by_time.setdefault(r["time"], []).append((float(r["size"]), float(r["size_density"])))
    panel(svg, 2 * W, "size distribution n_k (pivots)", "k", "n_k / n1(0)",
          [(f"t = {float(t):.3g}", pts) for t, pts in by_time.items()], True, True, (0, 5), (-12, 0))
    svg.append("</svg>")
    open(target, "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:7])
