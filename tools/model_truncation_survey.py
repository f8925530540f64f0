#!/usr/bin/env python3
"""Replays the tolerance scans of hard-spheres, viscoelastic, mixture and rough on long sequences (theory.md §6,
"The other models' scans"): rule (6.1) as before and (6.3) as now (for rough also the window rule (19.100)–(19.101)
of theory.md §19.23 that its scans use now, against (6.3)), against the sequence's last order plus its
geometric remainder (its size the reference's uncertainty; a claim is judged only where that is below a quarter
of it). Reads the CSV of build/bin/gkt_model_sequences:

    python3 tools/model_truncation_survey.py model_sequences.csv
    build/bin/gkt_model_sequences rough > rough.csv && python3 tools/model_truncation_survey.py rough.csv --stops

Per model: its order cap and the highest order its estimate may read (the model's tables); arithmetic as the
library's, exact rationals of the doubles (the rules are truncation_survey.py's).
"""
import csv
import os
import sys
from collections import defaultdict
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from truncation_survey import choose_order, estimate, estimate_confirmed, reference  # noqa: E402

# model -> (order cap of its scan, highest order its estimate may read)
CAPS = {"hard-spheres": (40, 43), "viscoelastic": (6, 8), "mixture": (12, 14), "rough": (8, 10)}
TOLERANCES = [F(1, 10**k) for k in range(3, 13)]


def scan(seq, tol, new, cap, highest):
    """The model's scan: (order, value, error, met)."""
    def value_at(n):
        if n + 2 > highest or any(seq.get(m) is None for m in (n, n + 1, n + 2)):
            return None
        v = [seq[n], seq[n + 1], seq[n + 2]]
        return estimate_confirmed(*v, seq.get(n + 3) if n + 3 <= highest else None) if new else estimate(*v)
    return choose_order(value_at, tol, cap)


def estimate_windowed(v):
    """(19.100)-(19.101): (6.3) widened to the spread of every later order v[1:] plus the (6.1) error of v[-3]."""
    base = list(estimate_confirmed(v[0], v[1], v[2], v[3] if len(v) > 3 else None))
    if len(v) > 3:
        spread = max(abs(x - v[0]) for x in v[1:])
        base[1] = max(base[1], spread + estimate(v[-3], v[-2], v[-1])[1])
    return tuple(base)


def scan_windowed(seq, tol, cap, highest):
    """rough_model.cpp's tolerance scan: the window runs to the highest order of the tables."""
    def value_at(n):
        if n + 2 > highest or any(seq.get(m) is None for m in range(n, highest + 1)):
            return None
        return estimate_windowed([seq[m] for m in range(n, highest + 1)])
    return choose_order(value_at, tol, cap)


def main(path, stops=False):
    data = defaultdict(dict)
    with open(path) as f:
        for r in csv.DictReader(f):
            data[(r["model"], r["state"], r["column"])][int(r["order"])] = F(float(r["value"]))
    worst, changed, counted = {}, [], defaultdict(int)
    for (model, state, column), seq in sorted(data.items()):
        cap, highest = CAPS[model]
        ref, unc = reference(seq)
        for tol in TOLERANCES:
            out = [scan(seq, tol, new, cap, highest) for new in (False, True)]
            if model == "rough":  # (6.3) against the window rule (19.100)
                out = [out[1], scan_windowed(seq, tol, cap, highest)]
            for new, o in zip((False, True), out):
                if o[3] and unc < o[2] / 4:
                    counted[(model, new)] += 1
                    ratio = float(abs(o[1] - ref) / o[2]) if o[2] > 0 else float("inf")
                    if (model, new) not in worst or ratio > worst[(model, new)][0]:
                        worst[(model, new)] = (ratio, state, column, float(tol), o[0], float(o[2]),
                                               float(abs(o[1] - ref)))
                if stops and new and model == "rough":
                    print("stop %s %s %.0e: order %d claimed %.2g met %s actual %.2g (reference uncertainty %.2g)" %
                          (state, column, tol, o[0], o[2], o[3], abs(o[1] - ref), unc))
            if out[0][0] != out[1][0] or out[0][3] != out[1][3]:
                changed.append((model, state, column, float(tol)) + tuple(
                    x for o in out for x in (o[0], float(o[2]), o[3], float(abs(o[1] - ref)))))
    print("changed stops: model state column tolerance | (6.1): order claimed met actual | (6.3): order claimed "
          "met actual (rough: (6.3) | window (19.100))")
    for c in changed:
        print("%s %s %s %.0e | %d %.2g %s %.2g | %d %.2g %s %.2g" % c)
    print("worst actual/claimed over judged stops that met the tolerance:")
    for key in sorted(worst):
        rule = ("(19.100)" if key[0] == "rough" else "(6.3)") if key[1] else ("(6.3)" if key[0] == "rough" else "(6.1)")
        print("%s %s (%d stops): %.3g at %s %s tol=%.0e order %d claimed %.2g actual %.2g" %
              ((key[0], rule, counted[key]) + worst[key]))


if __name__ == "__main__":
    main(sys.argv[1], "--stops" in sys.argv[2:])
