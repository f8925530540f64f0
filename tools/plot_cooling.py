#!/usr/bin/env python3
"""Plot T(t)/T(0) (log-log) and a2(t) from `gkt evolve` CSV files, one line per file, as a
standalone SVG. Standard library only.

    build/bin/gkt evolve tables/scenes/cooling_constant_alpha.toml --set t_end=1e7 --set points=41 --output /tmp/constant.csv
    build/bin/gkt evolve tables/scenes/cooling_viscoelastic.toml --output /tmp/viscoelastic.csv
    python3 tools/plot_cooling.py docs/cooling.svg "constant alpha = 0.8" /tmp/constant.csv "viscoelastic, delta = 0.1" /tmp/viscoelastic.csv
"""
import csv
import math
import sys


def main(target, pairs):
    series = [(label, list(csv.DictReader(open(path)))) for label, path in pairs]
    colours = ["#d95f02", "#1b9e77", "#7570b3"]
    w, h, pad = 420, 300, 56
    t_lo, t_hi = -1, 7
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * w}" height="{h + 30}" font-family="sans-serif" '
           'font-size="11">']

    def px(x0, t):
        return x0 + pad + (math.log10(t) - t_lo) / (t_hi - t_lo) * (w - pad - 12)

    panels = [("temperature", "T/T(0) (log)", -14, 0, True), ("a2", "a2", None, None, False)]
    a2_values = [float(r["a2"]) for _, rows in series for r in rows]
    a_lo, a_hi = min(a2_values + [0.0]), max(a2_values + [0.0])
    for p, (column, title, lo, hi, logy) in enumerate(panels):
        x0 = p * w
        if not logy:
            lo, hi = a_lo - 0.1 * (a_hi - a_lo), a_hi + 0.1 * (a_hi - a_lo)

        def py(v):
            y = math.log10(max(v, 10.0 ** lo)) if logy else v
            return 12 + (hi - y) / (hi - lo) * (h - pad)

        svg.append(f'<rect x="{x0 + pad}" y="12" width="{w - pad - 12}" height="{h - pad}" fill="none" stroke="#999"/>')
        for k in range(t_lo, t_hi + 1, 2):
            svg.append(f'<text x="{px(x0, 10.0 ** k)}" y="{h - pad + 28}" text-anchor="middle">1e{k}</text>')
        ticks = range(lo, hi + 1, 2) if logy else [lo + i * (hi - lo) / 4 for i in range(5)]
        for v in ticks:
            label = f"1e{v}" if logy else f"{v:.3f}"
            svg.append(f'<text x="{x0 + pad - 4}" y="{py(10.0 ** v if logy else v) + 4}" text-anchor="end">{label}</text>')
        svg.append(f'<text x="{x0 + w / 2}" y="{h - 8}" text-anchor="middle">time (initial mean free times) — {title}</text>')
        for i, (label, rows) in enumerate(series):
            pts = " ".join(f'{px(x0, float(r["time"])):.1f},{py(float(r[column])):.1f}' for r in rows if float(r["time"]) > 0)
            svg.append(f'<polyline points="{pts}" fill="none" stroke="{colours[i]}" stroke-width="1.6"/>')
            if p == 0:
                svg.append(f'<text x="{x0 + pad + 8}" y="{h - pad - 10 - 14 * i}" fill="{colours[i]}">{label}</text>')
    svg.append(f'<text x="8" y="{h + 24}">gkt evolve (CVODE), 3D, from a Maxwellian; Haff (t^-2) vs viscoelastic (t^-5/3)</text></svg>')
    open(target, "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    args = sys.argv[2:]
    main(sys.argv[1], list(zip(args[0::2], args[1::2])))
