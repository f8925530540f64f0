// Monte Carlo estimate of what the trial families beyond the products T_r S_p L_q do to the first-Sonine
// Navier–Stokes coefficients of rough spheres and disks about Maxwellians at the Maxwellian θ (docs/theory.md §19.21):
// every collision element of the lowest product and of the aligned (3D: (ŵŵ)°, (c·ŵ)(cŵ)° − (ŵ²/3)(cc)°, (ŵŵ)°·c,
// (c·ŵ)² − c²ŵ²/3) and chiral (3D: (c(c×ŵ))_sym, (c·ŵ)(ŵ(c×ŵ))_sym, c×ŵ; 2D: ŵ(c c⊥)_sym, ŵ c⊥) families from
// collisions drawn by tests/rough_monte_carlo.hpp (vector form, independent of the engine), the Galerkin systems of
// (19.41)–(19.43) solved with and without them, errors by a jackknife over 40 batches (the changes are correlated with
// the baseline, so their errors are much smaller than the values'). The chiral elements are the ones the engine
// cannot give (single triple products).
//   build-dev/bin/gkt_rough_trial_families_mc d alpha beta kappa collisions [seed]
//   e.g. gkt_rough_trial_families_mc 3 0.9 0.5 0.4 400000 11   (about 10 s)
// With a last argument `exact` the same systems are also solved with every element, N and G exact
// (RoughChiralFamilyElements, docs/theory.md §19.22) and printed as "exact" rows beside the Monte Carlo ones.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>
#include "rough_monte_carlo.hpp"
#include "transport/rough/rough_chiral_families.hpp"
using namespace gkt::test;
using M3 = std::array<std::array<double, 3>, 3>;
static double dd;
static int D;
static M3 outer_sym(const Vec3& a, const Vec3& b) {
  M3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = 0.5 * (a[i] * b[j] + a[j] * b[i]);
  return m;
}
static M3 traceless(M3 m) {
  double t = m[0][0] + m[1][1] + m[2][2];
  for (int i = 0; i < D; ++i) m[i][i] -= t / D;
  return m;
}
static double contract(const M3& a, const M3& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a[i][j] * b[i][j];
  return s;
}
static M3 axpy(const M3& a, double s, const M3& b) {
  M3 m = a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] += s * b[i][j];
  return m;
}
static M3 scal(double s, const M3& b) {
  M3 m = b;
  for (auto& r : m)
    for (auto& x : r) x *= s;
  return m;
}
// families: index 0.. ; returns tensor / vector / scalar values at (c, w)
struct Fam {
  std::vector<M3> t;
  std::vector<Vec3> v;
  std::vector<double> s;
};
static Fam families(const Vec3& c, const Vec3& w) {
  Fam f;
  const double x = dot3(c, c), y = dot3(w, w), p = dot3(c, w);
  const M3 cc = traceless(outer_sym(c, c));
  f.t.push_back(cc);
  if (D == 3) {
    f.t.push_back(traceless(outer_sym(w, w)));                             // T1 = (ww)°
    f.t.push_back(axpy(scal(p, traceless(outer_sym(c, w))), -y / 3, cc));  // T2' = p(cw)° − (y/3)(cc)°
    Vec3 cw = cross(c, w);
    f.t.push_back(outer_sym(c, cw));           // Tc1 = (c(c×w))_s
    f.t.push_back(scal(p, outer_sym(w, cw)));  // Tc2 = p (w(c×w))_s
  } else {
    Vec3 cp{-c[1], c[0], 0};
    f.t.push_back(scal(w[2], outer_sym(c, cp)));  // Tc = w (c c⊥)_s
  }
  const double h = (D + 2) / 2.0, hr = (D == 3 ? 1.5 : 0.5);
  Vec3 a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = c[k] * (x - h);
    b[k] = c[k] * (y - hr);
  }
  f.v.push_back(a);
  f.v.push_back(b);
  if (D == 3) {
    Vec3 F;
    for (int k = 0; k < 3; ++k) F[k] = w[k] * p - c[k] * y / 3;
    f.v.push_back(F);            // F = (ww)°·c
    f.v.push_back(cross(c, w));  // V = c×w
  } else {
    Vec3 V{-c[1] * w[2], c[0] * w[2], 0};
    f.v.push_back(V);
  }  // V = w c⊥
  f.s.push_back(x - D / 2.0);
  f.s.push_back(y - hr);
  if (D == 3) f.s.push_back(p * p - x * y / 3);  // P
  return f;
}
// degree (homogeneous new families) and C·∂_C action for product ones handled in G by finite formula
int main(int argc, char** argv) {
  if (argc < 6) {
    fprintf(stderr, "usage: d alpha beta kappa collisions [seed]\n");
    return 2;
  }
  D = atoi(argv[1]);
  dd = D;
  double alpha = atof(argv[2]), beta = atof(argv[3]), kappa = atof(argv[4]);
  long n = atol(argv[5]);
  int nb = 40;
  unsigned long seed = argc > 6 ? atol(argv[6]) : 7;
  const bool exact_too = std::string(argv[argc - 1]) == "exact";
  const double dr = (D == 3 ? 3 : 1);
  // Maxwellian θ: (2/d)<Δc²> = (2/(d_r τ))<Δw²>
  double etat = (1 + beta) * kappa / (2 * (1 + kappa));
  auto dc = [&](double tau) {
    return -(1 - alpha * alpha) / 2 - (dd - 1) * etat * (1 - etat) + (dd - 1) * etat * etat * tau;
  };
  auto dw = [&](double tau) { return (dd - 1) * (etat / kappa) * (-tau + (etat / kappa) * (1 + tau)); };
  double lo = 1e-6, hi = 1e6;
  for (int it = 0; it < 200; ++it) {
    double m = std::sqrt(lo * hi);
    double g = (2 / dd) * dc(m) - (2 / (dr * m)) * dw(m);
    if (g < 0)
      lo = m;
    else
      hi = m;
  }
  double tau = std::sqrt(lo * hi), theta = tau * kappa, z = -(2 / dd) * dc(tau);
  if (beta == -1) {
    printf("beta=-1: spin decoupled\n");
    return 0;
  }

  printf("d=%d alpha=%g beta=%g kappa=%g theta=%.6f zeta*=%.6f\n", D, alpha, beta, kappa, theta, z * (dd + 2) / 4);
  RoughCollisionSampler smp(D, alpha, beta, kappa, theta, seed);
  const double lam = std::sqrt(tau);
  Fam f0 = families({1, 0.3, 0.2}, {0.1, 0.2, 0.5});
  int nt = f0.t.size(), nv = f0.v.size(), ns = f0.s.size();
  // accumulators per batch
  std::vector<std::vector<double>> Lt(nb, std::vector<double>(nt * nt)), Lv(nb, std::vector<double>(nv * nv)),
      Ls(nb, std::vector<double>(ns * ns)), W(nb, std::vector<double>(1));
  gsl_rng* r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, seed + 1);
  for (long i = 0; i < n; ++i) {
    int bt = i % nb;
    RoughCollision c;
    Vec3 s{};
    for (int k = 0; k < D; ++k) {
      c.w[0][k] = gsl_ran_gaussian(r, std::sqrt(0.5));
      c.w[1][k] = gsl_ran_gaussian(r, std::sqrt(0.5));
      s[k] = gsl_ran_gaussian(r, 1);
    }
    for (int k = (D == 3 ? 0 : 2); k < 3; ++k) {
      c.w[2][k] = gsl_ran_gaussian(r, lam * std::sqrt(0.5));
      c.w[3][k] = gsl_ran_gaussian(r, lam * std::sqrt(0.5));
    }
    double nn = std::sqrt(dot3(s, s));
    for (auto& q : s) q /= nn;
    double u = 0;
    for (int k = 0; k < 3; ++k) u += s[k] * (c.w[0][k] - c.w[1][k]);
    if (u < 0) {
      for (auto& q : s) q = -q;
    }
    apply_rough_rule(c, s, alpha, beta, kappa);
    double wt = c.weight;
    auto sc = [&](const Vec3& w) {
      Vec3 o;
      for (int k = 0; k < 3; ++k) o[k] = w[k] / lam;
      return o;
    };
    Fam a1 = families(c.w[0], sc(c.w[2])), a2 = families(c.w[1], sc(c.w[3])), b1 = families(c.w[4], sc(c.w[6]));
    W[bt][0] += wt;
    for (int p = 0; p < nt; ++p) {
      M3 dphi = axpy(a1.t[p], -1, b1.t[p]);
      for (int q = 0; q < nt; ++q) Lt[bt][p * nt + q] += wt * (contract(a1.t[q], dphi) + contract(a2.t[q], dphi));
    }
    for (int p = 0; p < nv; ++p) {
      Vec3 dphi;
      for (int k = 0; k < 3; ++k) dphi[k] = a1.v[p][k] - b1.v[p][k];
      for (int q = 0; q < nv; ++q) Lv[bt][p * nv + q] += wt * (dot3(a1.v[q], dphi) + dot3(a2.v[q], dphi));
    }
    for (int p = 0; p < ns; ++p) {
      double dphi = a1.s[p] - b1.s[p];
      for (int q = 0; q < ns; ++q) Ls[bt][p * ns + q] += wt * (a1.s[q] + a2.s[q]) * dphi;
    }
  }
  // Maxwellian products N and G (G_pq = <ψ_q C·∂_C φ_p>, by finite difference of the scaling, exact for polynomials:
  // derivative d/dt φ(e^t C) at 0)
  long nm = 4000000;
  std::vector<double> Nt(nt * nt), Gt(nt * nt), Nv(nv * nv), Gv(nv * nv), Ns(ns * ns), Gs(ns * ns);
  for (long i = 0; i < nm; ++i) {
    Vec3 c{}, w{};
    for (int k = 0; k < D; ++k) c[k] = gsl_ran_gaussian(r, std::sqrt(0.5));
    for (int k = (D == 3 ? 0 : 2); k < 3; ++k) w[k] = gsl_ran_gaussian(r, std::sqrt(0.5));
    Fam f = families(c, w);
    const double e = 1e-4;
    Vec3 cp, wp, cm, wm;
    for (int k = 0; k < 3; ++k) {
      cp[k] = c[k] * (1 + e);
      wp[k] = w[k] * (1 + e);
      cm[k] = c[k] * (1 - e);
      wm[k] = w[k] * (1 - e);
    }
    Fam fp = families(cp, wp), fm = families(cm, wm);
    for (int p = 0; p < nt; ++p) {
      M3 dp = scal(1 / (2 * e), axpy(fp.t[p], -1, fm.t[p]));
      for (int q = 0; q < nt; ++q) {
        Nt[p * nt + q] += contract(f.t[p], f.t[q]);
        Gt[p * nt + q] += contract(dp, f.t[q]);
      }
    }
    for (int p = 0; p < nv; ++p) {
      Vec3 dp;
      for (int k = 0; k < 3; ++k) dp[k] = (fp.v[p][k] - fm.v[p][k]) / (2 * e);
      for (int q = 0; q < nv; ++q) {
        Nv[p * nv + q] += dot3(f.v[p], f.v[q]);
        Gv[p * nv + q] += dot3(dp, f.v[q]);
      }
    }
    for (int p = 0; p < ns; ++p) {
      double dp = (fp.s[p] - fm.s[p]) / (2 * e);
      for (int q = 0; q < ns; ++q) {
        Ns[p * ns + q] += f.s[p] * f.s[q];
        Gs[p * ns + q] += dp * f.s[q];
      }
    }
  }
  for (auto* v : {&Nt, &Gt, &Nv, &Gv, &Ns, &Gs})
    for (auto& x : *v) x /= nm;
  // exact orthogonality: new families (index >= base) vs product ones (< base)
  auto ortho = [&](std::vector<double>& m, int nf, int base) {
    for (int p = 0; p < nf; ++p)
      for (int q = 0; q < nf; ++q)
        if ((p < base) != (q < base)) m[p * nf + q] = 0;
  };
  ortho(Nt, nt, 1);
  ortho(Gt, nt, 1);
  ortho(Nv, nv, 2);
  ortho(Gv, nv, 2);
  ortho(Ns, ns, 2);
  ortho(Gs, ns, 2);
  // exact Maxwellian moments for product entries
  const double X1 = dd / 2, X2 = dd / 2 * (dd / 2 + 1), X3 = X2 * (dd / 2 + 2), Y1 = dr / 2, Y2 = dr / 2 * (dr / 2 + 1);
  auto solve = [](std::vector<std::vector<double>> a, std::vector<double> b) {
    size_t n = b.size();
    for (size_t c = 0; c < n; ++c) {
      size_t pv = c;
      for (size_t r = c + 1; r < n; ++r)
        if (std::fabs(a[r][c]) > std::fabs(a[pv][c])) pv = r;
      std::swap(a[c], a[pv]);
      std::swap(b[c], b[pv]);
      for (size_t r = c + 1; r < n; ++r) {
        double f = a[r][c] / a[c][c];
        for (size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
        b[r] -= f * b[c];
      }
    }
    std::vector<double> x(n);
    for (size_t r = n; r-- > 0;) {
      double s = b[r];
      for (size_t k = r + 1; k < n; ++k) s -= a[r][k] * x[k];
      x[r] = s / a[r][r];
    }
    return x;
  };
  // evaluation given L matrices (averaged), with family subset mask
  auto evaluate = [&](const std::vector<double>& lt, const std::vector<double>& lv, const std::vector<double>& ls,
                      const std::vector<int>& ti, const std::vector<int>& vi, const std::vector<int>& si) {
    std::array<double, 4> out{};
    {
      size_t m = ti.size();
      std::vector<std::vector<double>> A(m, std::vector<double>(m));
      std::vector<double> b(m, 0);
      b[0] = 1;
      for (size_t p = 0; p < m; ++p)
        for (size_t q = 0; q < m; ++q) {
          int P = ti[p], Q = ti[q];
          A[p][q] = lt[P * nt + Q] - z / 2 * Gt[P * nt + Q] + z / 2 * Nt[P * nt + Q];
        }
      auto a = solve(A, b);
      out[0] = (dd - 1) * a[0];
    }  // b_p = <ψ_p:Y2>/<Y2:Y2> (Y2 first)
    {
      size_t m = vi.size();
      std::vector<std::vector<double>> A(m, std::vector<double>(m)), B(m, std::vector<double>(m));
      std::vector<double> drive(m, 0), ft(m, 0), fr(m, 0);
      // <ψ1·ψ1> = <x(x-h)^2>, <ψ2·ψ2> = <x><(y-hr)^2>, <ψ1·ψ2> = 0
      const double h = (dd + 2) / 2, hr = dr / 2;
      const double n1 = X3 - 2 * h * X2 + h * h * X1;
      const double n2 = X1 * (Y2 - 2 * hr * Y1 + hr * hr);
      for (size_t p = 0; p < m; ++p) {
        int P = vi[p];
        if (P == 0) {
          drive[p] = n1;
          ft[p] = n1;
          fr[p] = 0;
        }
        if (P == 1) {
          drive[p] = n2;
          ft[p] = 0;
          fr[p] = n2;
        }
        for (size_t q = 0; q < m; ++q) {
          int Q = vi[q];
          A[p][q] = lv[P * nv + Q] - z / 2 * (Gv[P * nv + Q] + Nv[P * nv + Q]);
          B[p][q] = lv[P * nv + Q] - z / 2 * Gv[P * nv + Q];
        }
      }
      // flux <c x·ψ>: ψ1 -> <x^2(x-h)> = X3 - h X2 = n1? check: n1 = <x (x-h)^2> = X3-2hX2+h^2X1 ; <x^2 (x-h)> = X3 - h
      // X2
      for (size_t p = 0; p < m; ++p) {
        int P = vi[p];
        if (P == 0) {
          ft[p] = X3 - h * X2;
          fr[p] = 0;
        }
      }
      // <c y·ψ1> = <x(x-h)><y> = (X2-hX1)Y1 = 0 ; <c x·ψ2> = X2 (Y1-hr) = 0 ; <c y·ψ2> = X1 (Y2 - hr Y1)
      for (size_t p = 0; p < m; ++p) {
        int P = vi[p];
        if (P == 1) {
          ft[p] = 0;
          fr[p] = X1 * (Y2 - hr * Y1);
        }
        if (P == 0) fr[p] = 0;
      }
      auto x = solve(A, drive);
      std::vector<double> cpl(m, 0);
      for (size_t p = 0; p < m; ++p)
        for (size_t q = 0; q < m; ++q) cpl[p] += z * Nv[vi[p] * nv + vi[q]] * x[q];
      auto y = solve(B, cpl);
      double nref = dd * (dd + 2) / 4, ref = nref * nref / (dd - 1);
      double kx = 0, ky = 0;
      for (size_t p = 0; p < m; ++p) {
        kx += (ft[p] + theta * fr[p]) * x[p];
        ky += (ft[p] + theta * fr[p]) * y[p];
      }
      out[1] = kx / ref;
      out[2] = ky / ref;
    }
    {
      size_t m = si.size();
      std::vector<std::vector<double>> A(m + 1, std::vector<double>(m + 1, 0));
      std::vector<double> rhs(m + 1, 0);
      const double split = 2 / (dd + dr * theta), scale = 4 / (dd + 2);
      // <(x-d/2)^2> = X2 - X1^2 = d/2 ; <(y-dr/2)^2> = dr/2
      for (size_t p = 0; p < m; ++p) {
        int P = si[p];
        double h = 0, e = 0;
        if (P == 0) {
          h = dd / 2;
          e = dd / 2;
        }
        if (P == 1) {
          h = dr / 2;
          e = 0;
        }
        for (size_t q = 0; q < m; ++q) {
          int Q = si[q];
          A[p][q] = ls[P * ns + Q] - z / 2 * Gs[P * ns + Q] + z / 2 * Ns[P * ns + Q];
        }
        A[p][m] = -scale * h;
        rhs[p] = scale * (split * h - (2 / dd) * e);
      }
      for (size_t q = 0; q < m; ++q) {
        int Q = si[q];
        A[m][q] = (Q == 0 ? dd / 2 : 0) + theta * (Q == 1 ? dr / 2 : 0);
      }
      auto s = solve(A, rhs);
      out[3] = -(2 / dd) * s[0] * dd / 2;
    }
    return out;
  };
  auto avg = [&](const std::vector<std::vector<double>>& acc, int skip) {
    std::vector<double> m(acc[0].size(), 0);
    double w = 0;
    for (int b = 0; b < nb; ++b) {
      if (b == skip) continue;
      for (size_t k = 0; k < m.size(); ++k) m[k] += acc[b][k];
      w += W[b][0];
    }
    for (auto& x : m) x /= w;
    return m;
  };
  std::vector<int> tp{0}, vp{0, 1}, sp{0, 1}, tall, vall, sall;
  for (int i = 0; i < nt; ++i) tall.push_back(i);
  for (int i = 0; i < nv; ++i) vall.push_back(i);
  for (int i = 0; i < ns; ++i) sall.push_back(i);
  std::vector<int> tnc{0}, tch{0}, vnc{0, 1}, vch{0, 1};
  if (D == 3) {
    tnc = {0, 1, 2};
    tch = {0, 3, 4};
    vnc = {0, 1, 2};
    vch = {0, 1, 3};
  } else {
    tch = {0, 1};
    vch = {0, 1, 2};
  }
  struct Case {
    const char* name;
    std::vector<int> t, v, s;
  };
  std::vector<Case> cases{
      {"product", tp, vp, sp}, {"+non-chiral", tnc, vnc, sall}, {"+chiral", tch, vch, sp}, {"+all", tall, vall, sall}};
  const char* col[4] = {"eta*", "kappa*", "mu*", "eta_b*"};
  std::vector<std::array<double, 4>> full;
  for (auto& cs : cases) full.push_back(evaluate(avg(Lt, -1), avg(Lv, -1), avg(Ls, -1), cs.t, cs.v, cs.s));
  std::vector<std::vector<std::array<double, 4>>> jk(cases.size());
  for (int b = 0; b < nb; ++b) {
    auto lt = avg(Lt, b), lv = avg(Lv, b), ls = avg(Ls, b);
    for (size_t i = 0; i < cases.size(); ++i) jk[i].push_back(evaluate(lt, lv, ls, cases[i].t, cases[i].v, cases[i].s));
  }
  for (size_t i = 0; i < cases.size(); ++i) {
    printf("%-12s", cases[i].name);
    for (int k = 0; k < 4; ++k) {
      double m = 0;
      for (auto& a : jk[i]) m += a[k];
      m /= nb;
      double v = 0;
      for (auto& a : jk[i]) v += (a[k] - m) * (a[k] - m);
      double err = std::sqrt(v * (nb - 1.0) / nb);
      if (i == 0)
        printf(" %s=%.5f±%.5f", col[k], full[i][k], err);
      else {
        double dm = 0;
        std::vector<double> dv;
        for (int b = 0; b < nb; ++b) dv.push_back(jk[i][b][k] - jk[0][b][k]);
        for (double x : dv) dm += x;
        dm /= nb;
        double vv = 0;
        for (double x : dv) vv += (x - dm) * (x - dm);
        printf(" d%s=%+.5f±%.5f", col[k], full[i][k] - full[0][k], std::sqrt(vv * (nb - 1.0) / nb));
      }
    }
    printf("\n");
  }
  if (exact_too) {
    const gkt::detail::RoughChiralFamilyElements ex(D, gkt::Rational::parse(argv[2]), gkt::Rational::parse(argv[3]),
                                                    gkt::Rational::parse(argv[4]));
    std::vector<double> elt(nt * nt), elv(nv * nv), els(ns * ns);
    const auto fill = [&](int rank, int m, std::vector<double>& l, std::vector<double>& nn, std::vector<double>& gg) {
      for (int p = 0; p < m; ++p)
        for (int q = 0; q < m; ++q) {
          l[p * m + q] = ex.element(rank, p, q, tau);
          nn[p * m + q] = ex.maxwell_product_at(rank, p, q);
          gg[p * m + q] = ex.maxwell_scaling_product_at(rank, p, q);
        }
    };
    fill(2, nt, elt, Nt, Gt);
    fill(1, nv, elv, Nv, Gv);
    fill(0, ns, els, Ns, Gs);
    const auto base = evaluate(elt, elv, els, cases[0].t, cases[0].v, cases[0].s);
    for (auto& cs : cases) {
      const auto e = evaluate(elt, elv, els, cs.t, cs.v, cs.s);
      printf("exact %-12s", cs.name);
      for (int k = 0; k < 4; ++k) printf(" %s=%.6f (d%+.6f)", col[k], e[k], e[k] - base[k]);
      printf("\n");
    }
  }
  // print the L matrices (full average) for inspection
  auto lt = avg(Lt, -1), lv = avg(Lv, -1), ls = avg(Ls, -1);
  printf("L tensor:\n");
  for (int p = 0; p < nt; ++p) {
    for (int q = 0; q < nt; ++q) printf(" %9.5f", lt[p * nt + q]);
    printf("\n");
  }
  printf("L vector:\n");
  for (int p = 0; p < nv; ++p) {
    for (int q = 0; q < nv; ++q) printf(" %9.5f", lv[p * nv + q]);
    printf("\n");
  }
  printf("L scalar:\n");
  for (int p = 0; p < ns; ++p) {
    for (int q = 0; q < ns; ++q) printf(" %9.5f", ls[p * ns + q]);
    printf("\n");
  }
  printf("N tensor diag:");
  for (int p = 0; p < nt; ++p) printf(" %.4f", Nt[p * nt + p]);
  printf("  G/N:");
  for (int p = 0; p < nt; ++p) printf(" %.3f", Gt[p * nt + p] / Nt[p * nt + p]);
  printf("\n");
  // jackknife errors of L entries (new-product couplings)
  printf("L errors tensor row0/col0:");
  for (int q = 0; q < nt; ++q) {
    double m = 0, v = 0;
    std::vector<double> e;
    for (int b = 0; b < nb; ++b) e.push_back(avg(Lt, b)[q]);
    for (double x : e) m += x;
    m /= nb;
    for (double x : e) v += (x - m) * (x - m);
    printf(" %.5f", std::sqrt(v * (nb - 1.0) / nb));
  }
  printf("\n");
  return 0;
}
