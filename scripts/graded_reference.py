#!/usr/bin/env python3
"""Reference data for stickslip-graded (crates/graded/tests/data/), computed with mpmath.

Precision: mp.dps = 40 (about 40 significant digits); mp.quad (tanh-sinh) with the interval
split at s = x, s = x +- y, s = x +- 10 y and at the patch edges +-a, so that every piece is
smooth apart from its end points.

Everything is computed independently of the Rust code:
  * I_k and J_k by quadrature of their defining integrals (FORMULAS.md A1), not the Gamma form;
  * stresses by direct quadrature of FORMULAS.md A2 in the variable s;
  * the relative approach by quadrature of the two pressure integrals (FORMULAS.md A4);
  * the odd surface integral int p(s) sgn(x-s)|x-s|^-k ds by quadrature (FORMULAS.md A3).

Inputs are Python floats (exactly representable f64), printed with repr(); mpmath converts them
exactly. Deterministic (no random numbers). Run:  python3 scripts/graded_reference.py
"""
from mpmath import mp, mpf, quad, cos, sin, atan2, sqrt, pi, log

mp.dps = 40
OUT = "crates/graded/tests/data/"


def weak(f, x, lo, hi, k):
    """int_lo^hi f(t) |x - t|^-k dt with x = lo or x = hi, after the substitution
    |t - x| = v^m, m = 1/(1-k), which turns the singular factor into the constant m."""
    m = 1 / (1 - k)
    span = (hi - lo) ** (1 / m)
    if x == lo:
        return m * quad(lambda v: f(lo + v ** m), [0, span])
    return m * quad(lambda v: f(hi - v ** m), [0, span])


def consts(k, nu):
    k, nu = mpf(k), mpf(nu)
    beta = sqrt((1 + k) * (1 - (1 + k) * nu) / (1 - nu))
    ik = quad(lambda t: cos(t) ** (k + 1) * cos(beta * t), [0, pi / 2])
    jk = quad(lambda t: cos(t) ** k * sin(t) * sin(beta * t), [0, pi / 2])
    return beta, ik, jk


def splits(x, y, a):
    pts = {-a, a}
    for c in (x, x - y, x + y, x - 10 * y, x + 10 * y):
        if -a < c < a:
            pts.add(c)
    return sorted(pts)


def stress(k, nu, mu, a, p0, x, y):
    k, mu, a, p0, x, y = map(mpf, (k, mu, a, p0, x, y))
    beta, ik, jk = consts(k, nu)
    g = (1 + k) / 2

    def amp(s):
        p = p0 * ((1 - s / a) * (1 + s / a)) ** g
        th = atan2(x - s, y)
        return -(p * cos(beta * th) / (2 * ik) + mu * p * sin(beta * th) / (2 * jk))

    def r3k(s):
        return ((x - s) ** 2 + y ** 2) ** ((3 + k) / 2)

    pts = splits(x, y, a)
    sxx = quad(lambda s: amp(s) * y ** k * (x - s) ** 2 / r3k(s), pts)
    syy = quad(lambda s: amp(s) * y ** (2 + k) / r3k(s), pts)
    sxy = quad(lambda s: amp(s) * y ** (1 + k) * (x - s) / r3k(s), pts)
    return sxx, syy, sxy


def stress_table():
    a, p0 = 0.75, 2.5
    rows = []
    for k in (0.01, 0.1, 0.5, 0.95):
        for nu in (0.1, 0.3, 0.45):
            if nu >= 1 / (1 + k):
                continue
            for mu in (0.0, 0.3, 1.0):
                for (xr, yr) in ((0.0, 1e-3), (0.3, 1e-3), (-0.9, 1e-3), (1.0, 1e-3),
                                 (-1.0, 1e-2), (1.3, 0.05), (0.5, 0.5), (-2.0, 1.5),
                                 (0.1, 4.0)):
                    x, y = xr * a, yr * a
                    rows.append((k, nu, mu, a, p0, x, y) + stress(k, nu, mu, a, p0, x, y))
    with open(OUT + "graded_stress.txt", "w") as f:
        f.write("# stickslip-graded stress reference: mpmath mp.dps = 40, mp.quad split at "
                "s = x, x+-y, x+-10y, +-a\n")
        f.write("# cylinder pressure p = p0 (1 - s^2/a^2)^((1+k)/2), q = mu p (FORMULAS.md A2)\n")
        f.write("# k nu mu a p0 x y sigma_xx sigma_yy sigma_xy\n")
        for r in rows:
            f.write(" ".join(repr(v) for v in r[:7]) + " " +
                    " ".join(mp.nstr(v, 25) for v in r[7:]) + "\n")


def near_surface_table():
    a, p0 = 1.0, 1.0
    rows = []
    for k in (0.1, 0.5):
        nu = 0.3
        for mu in (0.0, 0.5):
            for xr in (-1.0, -0.999, -0.5, 0.0, 0.25, 0.999, 1.0, 1.0000001, 1.5):
                x, y = xr * a, 1e-6 * a
                rows.append((k, nu, mu, a, p0, x, y) + stress(k, nu, mu, a, p0, x, y))
    with open(OUT + "graded_stress_near_surface.txt", "w") as f:
        f.write("# stickslip-graded near-surface stress reference (y/a = 1e-6): mpmath "
                "mp.dps = 40, mp.quad split at s = x, x+-y, x+-10y, +-a\n")
        f.write("# k nu mu a p0 x y sigma_xx sigma_yy sigma_xy\n")
        for r in rows:
            f.write(" ".join(repr(v) for v in r[:7]) + " " +
                    " ".join(mp.nstr(v, 25) for v in r[7:]) + "\n")


def approach_table():
    """delta(L) / (a^2/(2R)) = (1 - ratio)/k, ratio = int (1-t^2)^g (l-t)^-k / int (1-t^2)^g |t|^-k."""
    rows = []
    for k in (0.0, 1e-6, 1e-3, 0.1, 0.5, 0.9):
        for l in (1.0625, 1.25, 1.5, 2.0, 10.0, 1000.0):
            kk, ll = mpf(k), mpf(l)
            g = (1 + kk) / 2
            if k == 0.0:
                # homogeneous: (2/pi) int sqrt(1-t^2) (ln(l-t) - ln|t|) dt
                val = 2 / pi * (quad(lambda t: sqrt(1 - t * t) * log(ll - t), [-1, 1]) -
                                quad(lambda t: sqrt(1 - t * t) * log(abs(t)), [-1, 0, 1]))
            else:
                num = quad(lambda t: (1 - t * t) ** g * (ll - t) ** (-kk), [-1, 1])
                # the |t|^-k singularity is removed by a substitution (see weak())
                w = lambda t: max(mpf(0), (1 - t) * (1 + t)) ** g
                den = weak(w, 0, -1, 0, kk) + weak(w, 0, 0, 1, kk)
                val = (1 - num / den) / kk
            rows.append((k, l, val))
    with open(OUT + "graded_approach.txt", "w") as f:
        f.write("# stickslip-graded relative approach reference: mpmath mp.dps = 40, mp.quad\n")
        f.write("# delta(L)/(a^2/(2R)) for the rigid cylinder, l = L/a (FORMULAS.md A4, B)\n")
        f.write("# k l delta_over_a2_2R\n")
        for k, l, v in rows:
            f.write(f"{k!r} {l!r} {mp.nstr(v, 25)}\n")


def odd_integral_table():
    """int_{-1}^{1} (1-t^2)^((1+k)/2) sgn(x-t)|x-t|^-k dt (a = 1, p0 = 1)."""
    rows = []
    for k in (0.1, 0.5, 0.9):
        kk = mpf(k)
        g = (1 + kk) / 2
        for x in (-1.0, -0.5, 0.0, 0.3, 0.999, 1.0, 1.5, -3.0):
            xx = mpf(x)
            w = lambda t: max(mpf(0), (1 - t) * (1 + t)) ** g
            if -1 < xx < 1:
                v = weak(w, xx, -1, xx, kk) - weak(w, xx, xx, 1, kk)
            elif xx == 1:
                v = weak(w, xx, -1, xx, kk)
            elif xx == -1:
                v = -weak(w, xx, xx, 1, kk)
            else:
                sg = 1 if xx > 1 else -1
                v = sg * quad(lambda t: w(t) * abs(xx - t) ** (-kk), [-1, 1])
            rows.append((k, x, v))
    with open(OUT + "graded_odd_integral.txt", "w") as f:
        f.write("# int_{-1}^{1} (1-t^2)^((1+k)/2) sgn(x-t) |x-t|^-k dt: mpmath mp.dps = 40, "
                "mp.quad split at x, +-1, |x-t|^-k removed by substitution (FORMULAS.md A3)\n")
        f.write("# k x value\n")
        for k, x, v in rows:
            f.write(f"{k!r} {x!r} {mp.nstr(v, 25)}\n")


if __name__ == "__main__":
    import sys
    parts = sys.argv[1:] or ["odd", "approach", "near", "stress"]
    if "odd" in parts:
        odd_integral_table()
    if "approach" in parts:
        approach_table()
    if "near" in parts:
        near_surface_table()
    if "stress" in parts:
        stress_table()
