#!/usr/bin/env python3
"""Replays the smooth-inelastic model's tolerance scans on long sequences (theory.md §6, rule (6.3)).

Reads the CSV of build/bin/gkt_truncation_sequences (Sonine orders 1 … 23, tail resolutions 1 … 24),
replays every scan (tolerances 1e-4 … 1e-11; columns a2, a3, ζ*, η*, κ*, μ*) with the former rule
((6.1) from three values, the plateau sum (6.2) from order 18) and with the turning-point check (6.3),
and compares each stop's claimed error with its distance to a reference: the Sonine sequence's last
order plus its geometric remainder, or the tail scheme's where that has the smaller last change.

    python3 tools/truncation_survey.py sequences_2d.csv sequences_3d.csv

Arithmetic mirrors the library's: exact rationals of the doubles (fractions.Fraction).
"""
import csv
import sys
from collections import defaultdict
from fractions import Fraction as F

COLUMNS = ["a2", "a3", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"]
SONINE_MAX_ORDER = 20  # kMaxOrder
FIRST_PLATEAU_ORDER = 18  # kFirstPlateauOrder
TAIL_MAX = 24  # kTailGalerkinMaxOrder
TAIL_FIRST_STOP = 10  # kTailFirstStoppingResolution
TOLERANCES = [F(1, 10**k) for k in range(4, 12)]


def estimate(v0, v1, v2):
    """(6.1): (value, error, converging)."""
    first, second = v1 - v0, v2 - v1
    if first == 0:
        return v0, abs(second), second == 0
    r = second / first
    if abs(r) >= 1:
        return v0, abs(first) + abs(second), False
    return v0, F(5, 4) * abs(first) / (1 - r), True


def changes_sign(v0, v1, v2):
    return (v1 - v0) * (v2 - v1) < 0


def estimate_confirmed(v0, v1, v2, v3):
    """(6.3): (6.1), but a sign change of the first two changes must be confirmed by the third."""
    if not changes_sign(v0, v1, v2):
        return estimate(v0, v1, v2)
    first, second = abs(v1 - v0), v2 - v1
    if v3 is None:
        return v0, first + abs(second), False
    third = v3 - v2
    if third * second < 0:
        return estimate(v0, v1, v2)
    q = third / second
    if q >= 1:
        return v0, first + abs(second) + abs(third), False
    return v0, F(5, 4) * (first + abs(second) / (1 - q)), True


def estimate_ratio_confirmed(v0, v1, v2, v3):
    """Variant: the ratio confirmed over Δ1, Δ2, Δ3 whatever its sign (geometric with the larger signed ratio)."""
    if changes_sign(v0, v1, v2) or v3 is None:
        return estimate_confirmed(v0, v1, v2, v3)
    first, second, third = v1 - v0, v2 - v1, v3 - v2
    if first == 0 or second == 0:
        return estimate(v0, v1, v2)
    r, q = second / first, third / second
    if q < 0:  # monotone, then a flip: (6.1)
        return estimate(v0, v1, v2)
    rho = max(r, q)
    if rho >= 1:
        return v0, abs(first) + abs(second) + abs(third), False
    return v0, F(5, 4) * abs(first) / (1 - rho), True


def estimate_growth_checked(v0, v1, v2, v3):
    """(6.3) plus: monotone changes that grow at the third (Δ3/Δ2 ≥ 1) cannot stop a scan."""
    if changes_sign(v0, v1, v2) or v3 is None:
        return estimate_confirmed(v0, v1, v2, v3)
    second, third = v2 - v1, v3 - v2
    if second != 0 and third / second >= 1:
        return v0, abs(v1 - v0) + abs(second) + abs(third), False
    return estimate(v0, v1, v2)


RULES = {3: estimate_growth_checked, 0: lambda v0, v1, v2, v3: estimate(v0, v1, v2), 1: estimate_confirmed, 2: estimate_ratio_confirmed}


def alternates(v0, v1, v2):
    first = v1 - v0
    if first == 0:
        return False
    r = (v2 - v1) / first
    return F(-2) <= r <= F(-1, 2)


def plateau_sum(v):
    if not alternates(v[0], v[1], v[2]) or not alternates(v[1], v[2], v[3]):
        return None
    e1 = [(v[i] + v[i + 1]) / 2 for i in range(3)]
    e2 = [(e1[i] + e1[i + 1]) / 2 for i in range(2)]
    e3 = (e2[0] + e2[1]) / 2
    means = e1 + e2 + [e3]
    smallest = min(abs(v[i] - v[i - 1]) for i in range(1, 4))
    return e3, max(F(5, 4) * (max(means) - min(means)), smallest / 2), True


def sonine_scan(seq, tol, new, summable):
    """choose_order with the model's Sonine value_at; seq[n] = v_n (n from 1). Returns (order, value, error, met)."""
    def value_at(n):
        if n + 2 not in seq:
            return None
        v = [seq[n], seq[n + 1], seq[n + 2]]
        nxt = seq.get(n + 3)
        est = RULES[new](*v, nxt)
        if summable and not (est[2] and est[1] < tol) and n >= FIRST_PLATEAU_ORDER and alternates(*v) and nxt is not None:
            s = plateau_sum(v + [nxt])
            if s is not None and s[1] < tol:
                est = s
        return est
    return choose_order(value_at, tol, SONINE_MAX_ORDER)


def choose_order(value_at, tol, cap):
    """models.hpp's choose_order: value_at(n) = (value, error, converging) or None. Returns (order, value, error, met)."""
    best, best_v, growing = 0, None, 0
    for n in range(1, cap + 1):
        est = value_at(n)
        if est is None:
            continue
        if est[2] and est[1] < tol:
            return n, est[0], est[1], True
        if best == 0 or est[1] < best_v[1]:
            best, best_v, growing = n, est, 0
        else:
            growing += 1
            if growing == 3:
                break
    return best, best_v[0], best_v[1], False


def tail_scan(seq, tol, new):
    highest = TAIL_MAX - 2
    best = None
    for n in range(TAIL_FIRST_STOP, highest + 1):
        if n + 2 not in seq:
            continue
        v = [seq[n], seq[n + 1], seq[n + 2]]
        est = RULES[new](*v, seq.get(n + 3))
        met = est[2] and est[1] < tol
        if met or best is None or est[1] < best[2]:
            best = (n, est[0], est[1], met)
        if met:
            break
    return best


def reference(seq):
    """The last value plus its geometric remainder, and the uncertainty (the last change)."""
    n = max(seq)
    d1, d2 = seq[n - 1] - seq[n - 2], seq[n] - seq[n - 1]
    r = d2 / d1 if d1 != 0 else F(0)
    if 0 < abs(r) < 1:  # the extrapolation itself is uncertain: at least its size
        rest = d2 * r / (1 - r)
        return seq[n] + rest, max(abs(d2), abs(rest))
    return seq[n], abs(d2) + abs(d1)


RULE = 1
KNOWN = {  # theory.md §6 table, column (b) (tail scheme to N = 29 extrapolated), its spread to (a)
    (2, "0.8", "a2"): (F(-0.0262441287448), F(1e-11)), (2, "0.8", "a3"): (F(-0.0121692034686), F(1e-11)),
    (2, "0.8", "cooling_rate"): (F(0.1790793648184), F(1e-12)),
    (2, "0.8", "shear_viscosity"): (F(1.0590287691318), F(2e-11)),
    (2, "0.8", "thermal_conductivity"): (F(1.1379606951), F(2e-9)),
    (2, "0.8", "density_heat_coefficient"): (F(0.3743865993), F(2e-9))}


def main(paths):
    data = defaultdict(dict)  # (scheme, d, alpha, column) -> {order: value}
    for path in paths:
        with open(path) as f:
            for row in csv.DictReader(f):
                for c in COLUMNS:
                    data[(row["scheme"], int(row["dimension"]), row["alpha"], c)][int(row["order"])] = F(float(row[c]))
    changed, worst = [], {}
    for (scheme, d, alpha, c), seq in sorted(data.items()):
        if float(alpha) == 1 and c in ("a2", "a3", "cooling_rate", "density_heat_coefficient"):
            continue  # exactly 0 at α = 1
        full = {"sonine": 23, "tail": TAIL_MAX}  # complete sequences only (a run still writing is skipped)
        if set(range(1, full[scheme] + 1)) - set(seq):
            continue
        refs = [reference(s) for k, s in (("sonine", data.get(("sonine", d, alpha, c))),
                                          ("tail", data.get(("tail", d, alpha, c))))
                if s and not set(range(1, full[k] + 1)) - set(s)]
        ref, unc = KNOWN.get((d, alpha, c)) or min(refs, key=lambda x: x[1])
        for tol in TOLERANCES:
            out = []
            for new in (0, RULE):
                if scheme == "sonine":
                    o = sonine_scan(seq, tol, new, c in ("a2", "a3", "cooling_rate", "shear_viscosity",
                                                         "thermal_conductivity", "density_heat_coefficient"))
                else:
                    o = tail_scan(seq, tol, new)
                out.append(o)
                actual = abs(o[1] - ref)
                resolved = unc < o[2] / 4  # the reference is good enough to judge this claim
                if o[3] and resolved:
                    key = (scheme, bool(new))
                    ratio = float(actual / o[2]) if o[2] > 0 else float("inf")
                    if key not in worst or ratio > worst[key][0]:
                        worst[key] = (ratio, d, alpha, c, float(tol), o[0], float(o[2]), float(actual))
            (o_old, o_new) = out
            if o_old[0] != o_new[0] or o_old[3] != o_new[3]:
                changed.append((scheme, d, alpha, c, float(tol), o_old[0], float(o_old[2]), o_old[3],
                                float(abs(o_old[1] - ref)), o_new[0], float(o_new[2]), o_new[3],
                                float(abs(o_new[1] - ref)), float(unc)))
    print("changed stops: scheme d alpha column tolerance | old: order claimed met actual | new: order claimed "
          "met actual | reference uncertainty")
    for c in changed:
        print("%s %d %s %s %.0e | %d %.2g %s %.2g | %d %.2g %s %.2g | %.1g" % c)
    print("worst actual/claimed over stops that met the tolerance (reference uncertainty < claim/4):")
    for key in sorted(worst):
        w = worst[key]
        print("%s %s: %.3g at d=%d alpha=%s %s tol=%.0e order %d claimed %.2g actual %.2g" %
              ((key[0], "new" if key[1] else "old") + w))


if __name__ == "__main__":
    if sys.argv[1].startswith("--rule="):
        RULE = int(sys.argv.pop(1)[7:])
    main(sys.argv[1:])
