#!/usr/bin/env python3
"""Reference data for stickslip-rolling: Goryacheva (1973) viscoelastic rolling.

Solves the UNSCALED equations of Goryacheva, PMM 37(5) 1973 (seed 001; corrected
forms in docs/FORMULAS.md section D) with mpmath at mp.dps = 50:

  eq 19  [P - l^2/(8KR)] [I0(x1) K1(x2) + K0(x2) I1(x1)]
             + w (beta - alpha) l/(2KR) I1(x1) K1(x2) = 0,   x1 = l/(2 beta w), x2 = l/(2 alpha w)
  eq 20  d  = [P - l^2/(8KR)] (2KR/l) K0(x2)/K1(x2)
  eq 24  [(rho/2R)(2d+l-m-2aw+2bw) - delta] I1(y1) K0(y2)
             + [(rho/2R)(2d+l-m) - delta] I0(y1) K1(y2) = 0,   y1 = m/(2 beta w), y2 = m/(2 alpha w)
         (the positive prefactor m/(2K) of eq 24 is dropped: it does not move the root in (0, l])
  eq 25  C2, eq 27  Q, eq 28  M1 = P(d - beta w) + l^2 (alpha w - d)/(8KR)

mpmath's Bessel functions have an arbitrary exponent range, so arguments of 1e7 and more
are evaluated directly (I0(1e7) ~ 1e4342940).  The roots are found independently of the
Rust solver's bracket: the sign of the equation is scanned on a log grid over (0, l_H]
(resp. (0, l]); exactly one sign change is required, and the root is then polished by
plain bisection to a relative width of 1e-45.

Inputs are Python floats (IEEE f64) converted to mpf exactly, and printed with repr(), so
the Rust test reads back the very same f64 values.  The creep delta of each case is chosen
after solving for l and d, as a fraction of the partial-slip range (0, rho (l + 2d)/(2R)),
rounded to f64, and from then on is an exact input.

Units SI: E [Pa], R [m], P [N/m], alpha, beta [s], w [m/s]; delta, rho, nu dimensionless.
Output: crates/rolling/tests/data/goryacheva_reference.txt
"""

import os
from mpmath import mp, mpf, besseli, besselk, pi, sqrt

mp.dps = 50

MATERIALS = {
    # name: (E [Pa], nu, R [m], P [N/m], rho)
    "rubber": (5.0e6, 0.49, 0.05, 1.0e3, 0.8),
    "polymer": (3.0e9, 0.35, 0.01, 1.0e4, 0.3),
    # a large soft roller: contact length ~0.2 m, so x1 = l/(2 beta w) reaches ~1e7
    "bigrubber": (2.0e6, 0.49, 0.5, 2.0e4, 1.0),
}
VALUES = [1.0e-6, 1.0e-4, 1.0e-2, 1.0, 1.0e2, 1.0e4, 1.0e6]
SPEEDS = [0.01, 1.0, 100.0]
FRACS = [0.25, 0.6, 0.85]


def scan_root(f, lo, hi, n):
    """Log-spaced sign scan of f on [lo, hi]; returns the unique bracketing pair."""
    pts = [lo * (hi / lo) ** (mpf(i) / (n - 1)) for i in range(n)]
    pts[-1] = hi
    vals = [f(p) for p in pts]
    changes = [i for i in range(n - 1) if (vals[i] > 0) != (vals[i + 1] > 0)]
    assert len(changes) == 1, f"expected one sign change, got {changes}"
    i = changes[0]
    return pts[i], pts[i + 1]


def polish(f, lo, hi):
    """Plain bisection to a relative width of 1e-45: slow but beyond doubt."""
    flo = f(lo)
    assert (flo > 0) != (f(hi) > 0)
    while hi - lo > lo * mpf(10) ** (-45):
        mid = (lo + hi) / 2
        fm = f(mid)
        if fm == 0:
            return mid
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return (lo + hi) / 2


def solve_case(E, nu, R, P, rho, alpha, beta, w, delta_frac=None, delta=None):
    E, nu, R, P, rho = map(mpf, (E, nu, R, P, rho))
    a_, b_, w_ = mpf(alpha), mpf(beta), mpf(w)
    K = 4 * (1 - nu**2) / (pi * E)
    lH = sqrt(8 * K * R * P)

    def f19(l):
        x1, x2 = l / (2 * b_ * w_), l / (2 * a_ * w_)
        i0, i1 = besseli(0, x1), besseli(1, x1)
        k0, k1 = besselk(0, x2), besselk(1, x2)
        return (P - l**2 / (8 * K * R)) * (i0 * k1 + k0 * i1) + w_ * (b_ - a_) * l / (2 * K * R) * i1 * k1

    lo, hi = scan_root(f19, lH * mpf(10) ** (-16), lH, 120)
    l = polish(f19, lo, hi)
    x1, x2 = l / (2 * b_ * w_), l / (2 * a_ * w_)
    d = (P - l**2 / (8 * K * R)) * (2 * K * R / l) * besselk(0, x2) / besselk(1, x2)

    if delta is None:
        delta = float(delta_frac * rho * (l + 2 * d) / (2 * R))
    dl = mpf(delta)

    def f24(m):
        y1, y2 = m / (2 * b_ * w_), m / (2 * a_ * w_)
        s = 2 * d + l - m
        return (rho / (2 * R) * (s - 2 * a_ * w_ + 2 * b_ * w_) - dl) * besseli(1, y1) * besselk(0, y2) + (
            rho / (2 * R) * s - dl
        ) * besseli(0, y1) * besselk(1, y2)

    mlo, mhi = scan_root(f24, l * mpf(10) ** (-16), l, 120)
    m = polish(f24, mlo, mhi)
    y1 = m / (2 * b_ * w_)
    s = 2 * d + l - m
    r = besseli(1, y1) / besseli(0, y1)
    C2 = m / (2 * K) * (rho / (2 * R) * (s - 2 * a_ * w_) - dl - (rho / (2 * R) * (s - 2 * a_ * w_ + 2 * b_ * w_) - dl) * r)
    Q = -rho * P + rho * m**2 / (8 * K * R) - m / (2 * K) * (rho / (2 * R) * (s - 2 * a_ * w_ + 2 * b_ * w_) - dl) * r
    M1 = P * (d - b_ * w_) + l**2 * (a_ * w_ - d) / (8 * K * R)
    return delta, l, d, m, C2, Q, M1, x1, y1


def main():
    out = os.path.join(os.path.dirname(__file__), "..", "crates", "rolling", "tests", "data", "goryacheva_reference.txt")
    rows = []
    idx = 0
    for name, (E, nu, R, P, rho) in MATERIALS.items():
        for w in SPEEDS:
            for i, beta in enumerate(VALUES):
                for alpha in VALUES[i + 1 :]:
                    frac = FRACS[idx % len(FRACS)]
                    idx += 1
                    res = solve_case(E, nu, R, P, rho, alpha, beta, w, delta_frac=frac)
                    rows.append((name, E, nu, R, P, rho, alpha, beta, w) + res)
        # near-elastic pairs: alpha = beta (1 + 2^-30), both small and large relaxation times
        for beta in (1.0e-6, 1.0, 1.0e6):
            alpha = beta * (1.0 + 2.0**-30)
            res = solve_case(E, nu, R, P, rho, alpha, beta, 1.0, delta_frac=0.5)
            rows.append((name, E, nu, R, P, rho, alpha, beta, 1.0) + res)
    with open(out, "w") as fh:
        fh.write("# Goryacheva (1973) rolling reference: unscaled eqs 19, 20, 24, 25, 27, 28 solved with mpmath, mp.dps = 50\n")
        fh.write("# generated by scripts/rolling_reference.py; inputs are exact f64 (repr), outputs rounded to 30 digits; SI units\n")
        fh.write("# material E nu R P rho alpha beta w delta l d m C2 Q M1 x1 y1\n")
        for r in rows:
            name = r[0]
            inputs = [repr(float(v)) for v in r[1:9]] + [repr(float(r[9]))]
            outs = [mp.nstr(v, 30) for v in r[10:]]
            fh.write(" ".join([name] + inputs + outs) + "\n")
    print(f"wrote {len(rows)} rows to {out}; max x1 = {mp.nstr(max(r[16] for r in rows), 5)}")


if __name__ == "__main__":
    main()
