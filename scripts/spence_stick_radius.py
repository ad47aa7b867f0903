#!/usr/bin/env python3
"""Stick-zone radius of a Hertz contact between dissimilar bodies under monotonic normal
loading with finite friction (Spence 1975, J. Elasticity 5; self-similar solution), in the
approximation that the shear traction does not change the (Hertz) pressure.

Derivation (docs/load-histories.md, "Dissimilar bodies"): with the contact radius a as the
load parameter (a = 1), the pressure rate is the flat-punch distribution 1/sqrt(1 - r^2). Write
the radial traction rate and the radial displacement rate as gradients, q = chi', u = psi'.
The longitudinal part of Cerruti's kernel has the symbol (1-nu)/(G k), the same as
Boussinesq's, so psi = B[chi] with the operator B of the frictionless normal problem, and
Sneddon's representation applies to the pair (chi, psi) with one function phi(t):
    chi(r) = phi(1)/sqrt(1-r^2) - int_r^1 phi'(t)/sqrt(t^2-r^2) dt,
    psi(r) = (2/E*) int_0^r phi(t)/sqrt(r^2-t^2) dt.
Stick zone r < c: no incremental slip, u_r(q) = -u_r(p), which gives
    phi_stick(t) = const + beta * (2/pi) t int_0^t (1-sqrt(1-r^2))/(r sqrt(t^2-r^2)) dr,
    phi_stick'(t) = beta * (2/pi) artanh(t)                                   (A)
Slip annulus c < r < 1: q = -sigma f p, chi = sigma f arccos(r), which gives
    phi_slip'(t) = -sigma f (2/pi) t K(k'),  k' = sqrt(1 - t^2)                  (B)
(K the complete elliptic integral of the first kind, modulus k'). phi continuous at c fixes
the constant; phi' continuous at c (a jump would make chi log-singular and the traction rate
non-integrable at the stick edge) gives, with sigma = -sign(beta),
    |beta| / f = c K(sqrt(1 - c^2)) / artanh(c).                                (C)

This script checks (A) and (B) by adaptive quadrature (tanh-sinh, mp.dps = 30) against the
closed forms at several t to 1e-20, then solves (C) for c at the listed beta/f to 1e-25
(findroot, bracketed). The values written are correct to at least 20 digits.
Output: crates/normal/tests/data/spence_stick_radius.tsv, columns beta_over_f, c_over_a.
"""
import os
from mpmath import mp, mpf, quad, sqrt, atanh, ellipk, pi, diff, findroot, acos, asin

mp.dps = 30
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "normal", "tests", "data",
                   "spence_stick_radius.tsv")


def k_comp(t):
    """K with modulus sqrt(1 - t^2) (mpmath's ellipk takes the parameter m = k^2)."""
    return ellipk(1 - t * t)


def phi_h(t):
    # r = t sin(theta): the Abel integral without its endpoint singularity.
    return 2 / pi * quad(lambda th: (1 - sqrt(1 - (t * mp.sin(th)) ** 2)) / mp.sin(th),
                         [0, pi / 2])


def slip_potential(t):
    # int_t^1 r arccos(r) / sqrt(r^2 - t^2) dr, r = t cosh(s) would do; use r^2 = t^2 + v^2.
    return quad(lambda v: acos(sqrt(t * t + v * v)) * 1, [0, sqrt(1 - t * t)])


for t in [mpf("0.1"), mpf("0.3"), mpf("0.5"), mpf("0.7"), mpf("0.9")]:
    a = diff(phi_h, t)
    b = 2 / pi * atanh(t)
    assert abs(a - b) < mpf(10) ** -20, ("(A)", t, a, b)
    # (B): phi_slip'(t) = (2/pi) sigma f d/dt int_t^1 r arccos(r)/sqrt(r^2-t^2) dr.
    a = 2 / pi * diff(slip_potential, t)
    b = -2 / pi * t * k_comp(t)
    assert abs(a - b) < mpf(10) ** -20, ("(B)", t, a, b)


def ratio(c):
    return c * k_comp(c) / atanh(c)


ROWS = ["0.25", "0.5", "0.75", "1", "1.25", "1.5", "2", "3", "4"]
out = []
for s in ROWS:
    target = mpf(s)
    # ratio decreases from +inf (c -> 0) to 0 (c -> 1): bisect for a bracket, then refine.
    lo, hi = mpf("1e-12"), 1 - mpf("1e-12")
    for _ in range(60):
        mid = (lo + hi) / 2
        if ratio(mid) > target:
            lo = mid
        else:
            hi = mid
    c = findroot(lambda x: ratio(x) - target, (lo, hi), solver="anderson")
    assert abs(ratio(c) - target) < mpf(10) ** -25, (s, c)
    out.append((s, c))

with open(OUT, "w") as fh:
    fh.write("# Spence (1975) self-similar stick radius of a Hertz contact, monotonic normal "
             "loading, pressure unaffected by the shear: |beta|/f = c K(sqrt(1-c^2)) / artanh(c); "
             "mpmath mp.dps = 30; scripts/spence_stick_radius.py\n")
    fh.write("# beta_over_f\tc_over_a\n")
    for s, c in out:
        fh.write(f"{s}\t{mp.nstr(c, 22)}\n")
print(open(OUT).read())
