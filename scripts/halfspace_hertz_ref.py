#!/usr/bin/env python3
"""Reference values for Hertz contacts (stickslip-halfspace).

1. Elliptic Hertz contact (Johnson, Contact Mechanics, eqs 3.39-3.41, 4.40): for a radius ratio
   lam = R'_major/R'_minor >= 1 solve
       (E(m) - (1-m) K(m)) / ((1-m) (K(m) - E(m))) = lam
   for m = e^2 with mpmath findroot, then for P = E* = R'_major = 1:
       a^3 = 3 (K - E) / (pi m),  b = a sqrt(1 - m),  p0 = 3 / (2 pi a b),  delta = 3 K / (2 pi a).
   (circle: a^3 = 3/4). Output tests/data/hertz_ellipse.csv.
2. 2D Hertz relative approach: delta(x0) = (2/(pi E*)) int_{-a}^{a} p(s) ln(|x0 - s| / |s|) ds
   for a = 1, R = 1 (so p0 = a E*/(2R) = 1/2 with E* = 1), computed by tanh-sinh quadrature.
   Output tests/data/hertz_line_approach.csv.
Precision mp.dps = 40. Inputs are exactly representable doubles, printed with repr().
"""
from mpmath import mp, mpf, ellipk, ellipe, findroot, pi, sqrt, log, quad, cbrt

mp.dps = 40

RATIOS = [1.0, 1.0000001, 1.5, 2.0, 4.0, 10.0, 16.0, 100.0, 1000.0, 1e4, 1e6]
XI = [0.25, 0.5, 1.0, 1.0009765625, 1.5, 2.0, 10.0, 1000.0, 1e8]


def ellipse(lam):
    lam = mpf(lam)
    if lam == 1:
        m = mpf(0)
        n = pi / 4
        k = pi / 2
    else:
        # solve in t = ln(b/a): m = 1 - exp(2 t)
        def g(t):
            mc = mp.exp(2 * t)
            m = 1 - mc
            K, E = ellipk(m), ellipe(m)
            return log((E - mc * K) / (mc * (K - E))) - log(lam)
        t0 = -mpf(2) / 3 * log(lam)
        t = findroot(g, (t0 - 1, min(t0 + 1, -mpf(10) ** -20)), solver="anderson")
        mc = mp.exp(2 * t)
        m = 1 - mc
        k = ellipk(m)
        n = (k - ellipe(m)) / m
    a = cbrt(3 * n / pi)
    b = a * sqrt(1 - m)
    p0 = 3 / (2 * pi * a * b)
    delta = 3 * k / (2 * pi * a)
    return m, a, b, p0, delta


def approach(xi):
    xi = mpf(xi)
    p = lambda s: mpf(1) / 2 * sqrt(1 - s * s)
    pts = sorted({mpf(-1), mpf(0), mpf(1)} | ({xi} if xi < 1 else set()))
    return 2 / pi * quad(lambda s: p(s) * (log(abs(xi - s)) - log(abs(s))), pts, maxdegree=12)


def main():
    with open("../crates/halfspace/tests/data/hertz_ellipse.csv", "w") as f:
        f.write("# Elliptic Hertz contact, P = E* = R'_major = 1, by mpmath (mp.dps = 40)\n")
        f.write("# generator: scripts/halfspace_hertz_ref.py; a along R'_major, b along R'_minor\n")
        f.write("ratio,m,a,b,p0,delta\n")
        for lam in RATIOS:
            vals = ellipse(lam)
            f.write(f"{lam!r}," + ",".join(mp.nstr(v, 25) for v in vals) + "\n")
    with open("../crates/halfspace/tests/data/hertz_line_approach.csv", "w") as f:
        f.write("# 2D Hertz approach relative to the surface points |x| = x0, a = R = E* = 1, P = pi/4\n")
        f.write("# delta = (2/(pi E*)) int p(s) ln(|x0-s|/|s|) ds by mpmath quad (mp.dps = 40)\n")
        f.write("# generator: scripts/halfspace_hertz_ref.py\n")
        f.write("x0,delta\n")
        for xi in XI:
            f.write(f"{xi!r}," + mp.nstr(approach(xi), 25) + "\n")


if __name__ == "__main__":
    main()
