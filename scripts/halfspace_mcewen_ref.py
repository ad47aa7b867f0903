#!/usr/bin/env python3
"""Reference stresses under a Hertz pressure plus Hertz-shaped shear on a half-plane, by direct
high-precision quadrature of Flamant's line-load kernels (Johnson eqs 2.15/2.16; FORMULAS.md B, C).

Convention (stickslip-halfspace): x along the surface, y depth into the body, compression negative,
p pushes into the body, q acts on the body in +x. Loading p = p0 sqrt(1 - s^2/a^2),
q = q0 sqrt(1 - s^2/a^2) on |s| <= a, a = 1.

    sigma(x, y) = int_{-a}^{a} [p(s) K_P(x - s, y) + q(s) K_Q(x - s, y)] ds
    K_P: xx = -2 X^2 y/(pi r^4), yy = -2 y^3/(pi r^4), xy = -2 X y^2/(pi r^4)
    K_Q: xx = -2 X^3/(pi r^4),   yy = -2 X y^2/(pi r^4), xy = -2 X^2 y/(pi r^4)

mpmath tanh-sinh quadrature with breakpoints at x, x +- y, x +- 10 y. Precision mp.dps = 40.
Output: crates/halfspace/tests/data/mcewen_flamant.csv
"""
from mpmath import mp, mpf, sqrt, pi, quad

mp.dps = 40
A = 1.0
P0 = 1.0
Q0 = 0.375

POINTS = [
    (0.3, 0.5), (-0.7, 0.25), (0.0, 1.0), (0.0, 0.78125), (0.5, 0.125), (-0.5, 0.0625),
    (1.0, 0.1), (-1.0, 0.1), (1.0, 0.001), (-1.0, 0.001), (1.25, 0.5), (-1.5, 0.25),
    (0.5, 1e-6), (-0.25, 1e-6), (0.0, 1e-6), (0.875, 1e-6), (1.0, 1e-6), (-1.0, 1e-6),
    (3.0, 2.0), (-10.0, 5.0), (0.25, 8.0), (-25.0, 0.5), (40.0, 30.0),
]


def field(x, y):
    x = mpf(x)
    y = mpf(y)
    a = mpf(A)

    def shape(s):
        return sqrt(1 - (s / a) ** 2)

    def kern(s, comp):
        X = x - s
        r4 = (X * X + y * y) ** 2
        if comp == 0:
            kp, kq = -2 * X * X * y, -2 * X ** 3
        elif comp == 1:
            kp, kq = -2 * y ** 3, -2 * X * y * y
        else:
            kp, kq = -2 * X * y * y, -2 * X * X * y
        return shape(s) * (mpf(P0) * kp + mpf(Q0) * kq) / (pi * r4)

    pts = {-a, a}
    for c in (x - 10 * y, x - y, x, x + y, x + 10 * y):
        if -a < c < a:
            pts.add(c)
    pts = sorted(pts)
    return [quad(lambda s: kern(s, c), pts, maxdegree=12) for c in range(3)]


def main():
    out = "../crates/halfspace/tests/data/mcewen_flamant.csv"
    with open(out, "w") as f:
        f.write("# Stresses under Hertz pressure + Hertz-shaped shear by mpmath quadrature of Flamant\n")
        f.write("# generator: scripts/halfspace_mcewen_ref.py, mp.dps = 40\n")
        f.write(f"# a = {A!r}, p0 = {P0!r}, q0 = {Q0!r}; y is depth, q acts on the body in +x\n")
        f.write("x,y,sxx,syy,sxy\n")
        for (x, y) in POINTS:
            s = field(x, y)
            f.write(f"{x!r},{y!r}," + ",".join(mp.nstr(v, 25) for v in s) + "\n")


if __name__ == "__main__":
    main()
