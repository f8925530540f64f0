#!/usr/bin/env python3
"""Derives the order-1 collisional-transfer averages of a dense mixture pair (docs/theory.md (17.26)-(17.27)).

<<Y>> = average of Y over f_i(v1) f_j(v2) Theta(s.g)(s.g) d s (normalised), Maxwellians f ~ exp(-theta v^2),
collision rule v1' = v1 - k (s.g) s with k = mu_ji (1 + alpha), Delta E_1 = m_i (v1'^2 - v1^2)/2,
c = sqrt(theta) v, X = c^2, vector Sonine S_1(X) = d/2 + 1 - X. With v1 = G + theta_j/(theta_i+theta_j) g,
v2 = G - theta_i/(theta_i+theta_j) g, G and g are independent Gaussians; by isotropy s is the first axis,
and the weight (s.g) on s.g > 0 gives the radial moments Gamma(1 + n/2) b^(-n/2), b = theta_i theta_j/(theta_i+theta_j).
Prints the entries of PairTransferMoments (mixture_collisional_transfer.hpp) at Sonine index 0 and 1.

    python3 tools/derive_mixture_transfer_first_sonine.py 3     # or 2; needs python3-sympy (Debian)
"""
import sys

import sympy as sp

d = int(sys.argv[1]) if len(sys.argv) > 1 else 3
ti, tj, k, mi = sp.symbols('theta_i theta_j k m_i', positive=True)
a, b = ti + tj, ti * tj / (ti + tj)
G = sp.symbols('G1:%d' % (d + 1), real=True)
g = sp.symbols('g1:%d' % (d + 1), real=True)
v1 = [G[c] + tj / a * g[c] for c in range(d)]
v2 = [G[c] - ti / a * g[c] for c in range(d)]
v1p = [v1[c] - (k * g[0] if c == 0 else 0) for c in range(d)]


def dot(u, w):
    return sum(u[c] * w[c] for c in range(d))


c1, c2, c1p = ([sp.sqrt(th) * x for x in v] for v, th in ((v1, ti), (v2, tj), (v1p, ti)))
X1, X2, X1p = dot(c1, c1), dot(c2, c2), dot(c1p, c1p)
energy = mi / 2 * (dot(v1p, v1p) - dot(v1, v1))


def sonine1(x):
    return sp.Rational(d, 2) + 1 - x


def gaussian(n, width):  # <x^n> for exp(-width x^2)
    return 0 if n % 2 else sp.factorial2(n - 1) / (2 * width) ** sp.Rational(n, 2)


def average(y):
    total = 0
    for powers, coefficient in sp.Poly(sp.expand(y), *G, *g).terms():
        value = coefficient * sp.gamma(1 + sp.Rational(powers[d], 2)) * b ** sp.Rational(-powers[d], 2)
        for c in range(d):
            value *= gaussian(powers[c], a)
        for c in range(1, d):
            value *= gaussian(powers[d + c], b)
        total += value
    return sp.factor(sp.simplify(total))


def traceless(c):  # Y(c) : s c2 = (s.c)(c.c2) - c^2 (s.c2)/d
    return c[0] * dot(c, c2) - dot(c, c) * c2[0] / d


entries = {
    'source_density[0]': c1p[0] - c1[0],
    'source_density[1]': c1p[0] * sonine1(X1p) - c1[0] * sonine1(X1),
    'source_temperature[0]': (c1p[0] - c1[0]) * (X2 - sp.Rational(d, 2)),
    'source_temperature[1]': (c1p[0] * sonine1(X1p) - c1[0] * sonine1(X1)) * (X2 - sp.Rational(d, 2)),
    'source_shear[0]': traceless(c1p) - traceless(c1),
    'shear_flux_partner[0]': g[0] * (c2[0] ** 2 - X2 / d),
    'shear_flux_self[0]': g[0] * (c1[0] ** 2 - X1 / d),
    'heat_flux_partner[0]': c2[0] * energy,
    'heat_flux_partner[1]': c2[0] * energy * sonine1(X2),
    'heat_flux_self[0]': c1[0] * energy,
    'heat_flux_self[1]': c1[0] * energy * sonine1(X1),
    'energy': energy,
    'energy_self': energy * X1,
    'energy_partner': energy * X2,
    'shear_gradient': g[0] * (2 * tj * v2[0] - 2 * ti * v1[0]),
    'cooling_gradient': g[0] ** 2 * 2 * tj * v2[0],
}
for name, y in entries.items():
    print(f'{name} = {average(y)}')
