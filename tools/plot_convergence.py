#!/usr/bin/env python3
"""Plot estimated truncation error against Sonine order from a `gkt table` CSV (one panel per
coefficient, one line per alpha), as a standalone SVG. Standard library only.

    python3 tools/plot_convergence.py tables/smooth_inelastic_orders_3d.csv docs/convergence.svg
"""
import csv
import math
import sys


def main(source, target):
    rows = list(csv.DictReader(open(source)))
    coefficients = [c for c in rows[0] if c + "_error" in rows[0]]
    alphas = sorted({r["alpha"] for r in rows}, key=float, reverse=True)
    colours = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"]
    width, height, pad = 300, 260, 48
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width * len(coefficients)}" height="{height + 40}" '
           'font-family="sans-serif" font-size="11">']
    lo, hi = -10, 1  # log10 error range
    for panel, name in enumerate(coefficients):
        x0 = panel * width
        orders = sorted({int(r["order"]) for r in rows})
        def px(n):
            return x0 + pad + (n - orders[0]) / (orders[-1] - orders[0]) * (width - pad - 10)
        def py(e):
            v = max(lo, min(hi, math.log10(e))) if e > 0 else lo
            return 10 + (hi - v) / (hi - lo) * (height - pad)
        svg.append(f'<rect x="{x0 + pad}" y="10" width="{width - pad - 10}" height="{height - pad}" '
                   'fill="none" stroke="#999"/>')
        for k in range(lo, hi + 1, 2):
            svg.append(f'<text x="{x0 + pad - 4}" y="{py(10.0 ** k) + 4}" text-anchor="end">1e{k}</text>')
        for n in orders:
            svg.append(f'<text x="{px(n)}" y="{height - pad + 24}" text-anchor="middle">{n}</text>')
        svg.append(f'<text x="{x0 + width / 2}" y="{height - 6}" text-anchor="middle">Sonine order ({name})</text>')
        for i, a in enumerate(alphas):
            pts = [(int(r["order"]), r[name + "_error"]) for r in rows if r["alpha"] == a]
            pts = [(n, float(e)) for n, e in pts if e not in ("inf", "nan")]
            if not pts:
                continue
            path = " ".join(f"{px(n):.1f},{py(e):.1f}" for n, e in pts)
            svg.append(f'<polyline points="{path}" fill="none" stroke="{colours[i % len(colours)]}" stroke-width="1.5"/>')
            if panel == 0:
                legend_y = height - pad - 8 - 14 * (len(alphas) - 1 - i)
                svg.append(f'<text x="{x0 + pad + 8}" y="{legend_y}" fill="{colours[i % len(colours)]}">'
                           f'alpha = {a}</text>')
    svg.append(f'<text x="8" y="{height + 30}">estimated truncation error (log scale) against order; '
               'source: gkt table, docs/performance.md</text></svg>')
    open(target, "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
