#!/usr/bin/env python3
"""Derives the first-Sonine collision integrals of a mixture pair (docs/theory.md (17.16)-(17.17)).

Maxwellians f_i, f_j of widths theta_i, theta_j (f ~ exp(-theta v^2)), collision rule
v1' = v1 - mu_ji (1 + alpha) (s.g) s. With v1 = G + theta_j/(theta_i+theta_j) g and
v2 = G - theta_i/(theta_i+theta_j) g, G and g are independent Gaussians; every integral is a Gaussian
moment in G, a hemisphere moment of s and a radial moment of |g|. Prints each integral divided by
c_d sqrt(1/theta_i + 1/theta_j) mu_ji (1 + alpha), in t = theta_i/theta_j and k = mu_ji (1 + alpha)(1 + t).

    python3 tools/derive_mixture_first_sonine.py 3     # or 2; needs python3-sympy (Debian)
"""
import sys

import sympy as sp

d = int(sys.argv[1]) if len(sys.argv) > 1 else 3
ti, tj, mu, al, r, t, k = sp.symbols('theta_i theta_j mu alpha r t k', positive=True)
G = sp.symbols('G1:%d' % (d + 1), real=True)
S = sp.symbols('s1:%d' % (d + 1), real=True)  # the unit vector s; g = r e_d
gvec = [0] * (d - 1) + [r]
v1 = [G[a] + tj / (ti + tj) * gvec[a] for a in range(d)]
v2 = [G[a] - ti / (ti + tj) * gvec[a] for a in range(d)]
sg = sum(S[a] * gvec[a] for a in range(d))
v1p = [v1[a] - mu * (1 + al) * sg * S[a] for a in range(d)]


def dot(u, w):
    return sum(u[a] * w[a] for a in range(d))


def vector(p, v, th):  # c S_p(c^2), c = sqrt(theta) v, S_1 = d/2 + 1 - c^2
    c = [sp.sqrt(th) * x for x in v]
    return [x * (1 if p == 0 else sp.Rational(d, 2) + 1 - th * dot(v, v)) for x in c]


def tensor(v, th):  # Y_2(c) = cc - c^2 I/d
    c = [sp.sqrt(th) * x for x in v]
    return [[c[a] * c[b] - (th * dot(v, v) / d if a == b else 0) for b in range(d)] for a in range(d)]


def average(expr):
    """∫∫ f̂_i f̂_j ∫ds Θ(s·g)(s·g) expr over G, s and g."""
    poly = sp.Poly(sp.expand(expr), *G)
    e = 0
    for powers, coeff in poly.terms():  # Gaussian moments of G, variance 1/(2(theta_i+theta_j))
        f = 1
        for n in powers:
            f = 0 if n % 2 else f * sp.factorial2(n - 1) * (1 / (2 * (ti + tj))) ** (n // 2)
        e += coeff * f
    poly = sp.Poly(sp.expand(e * sg), *S, r)
    tg = ti * tj / (ti + tj)
    area = 2 * sp.pi ** sp.Rational(d, 2) / sp.gamma(sp.Rational(d, 2))
    out = 0
    for powers, coeff in poly.terms():
        angles, n = powers[:d], powers[d]
        if any(x % 2 for x in angles[:d - 1]):
            continue
        hemisphere = sp.prod([sp.gamma(sp.Rational(x + 1, 2)) for x in angles]) / sp.gamma(
            sp.Rational(sum(angles) + d, 2))
        radial = (tg / sp.pi) ** sp.Rational(d, 2) * sp.gamma(sp.Rational(n + d, 2)) / (2 * tg ** sp.Rational(n + d, 2))
        out += coeff * hemisphere * radial * area
    c_d = sp.pi ** sp.Rational(d - 1, 2) / sp.gamma(sp.Rational(d, 2))
    out = sp.simplify(out / (c_d * sp.sqrt(1 / ti + 1 / tj) * mu * (1 + al)))
    out = sp.simplify(out.subs(ti, t * tj).subs(mu, k / ((1 + al) * (1 + t))))
    return sp.factor(out)


for p, q in ((0, 0), (1, 0), (1, 1)):
    delta = [a - b for a, b in zip(vector(p, v1p, ti), vector(p, v1, ti))]
    print('self_%d%d  =' % (p, q), average(dot(vector(q, v1, ti), delta)))
    print('other_%d%d =' % (p, q), average(dot(vector(q, v2, tj), delta)))
y1p, y1 = tensor(v1p, ti), tensor(v1, ti)
for name, trial in (('shear_self ', tensor(v1, ti)), ('shear_other', tensor(v2, tj))):
    print(name, '=', average(sum(trial[a][b] * (y1p[a][b] - y1[a][b]) for a in range(d) for b in range(d))))
