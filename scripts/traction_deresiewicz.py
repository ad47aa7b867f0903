#!/usr/bin/env python3
"""Reference values of the Mindlin-Deresiewicz energy bracket (FORMULAS.md section E; seed 002
eq. 3.5 with the corrected '+' sign):

    B(t) = 1 - (1-t)^(5/3) - (5t/6) (1 + (1-t)^(2/3)),   t = T*/(fP) in (0, 1],
    W = 9 (2 - nu) (fP)^2 / (10 G a) * B(t).

mpmath with mp.dps = 60: the direct form cancels about 3 log10(1/t) digits (24 at t = 1e-8), so
60 digits leave more than 30. It is cross-checked against the factored form
B = t^3 (s^2 + 3s + 1) / (6 (1 + s + s^2)^3), s = (1-t)^(1/3), to 1e-30 relative.
Inputs t are f64 (printed with repr(), converted to mpf exactly); they include both sides of
the former series/direct switch at t = 0.05.
Output: crates/traction/tests/data/deresiewicz_energy.tsv, columns t, bracket.
"""
import os
from mpmath import mp, mpf, cbrt

mp.dps = 60
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "traction", "tests", "data",
                   "deresiewicz_energy.tsv")

TS = [1e-8, 3e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 0.003, 0.01, 0.02, 0.03, 0.04, 0.049,
      0.04999999999999999, 0.05, 0.05000000000000001, 0.051, 0.06, 0.075, 0.1, 0.125, 0.2,
      0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.75, 0.8, 0.9, 0.95, 0.99, 0.999, 0.999999,
      0.9999999999999999, 1.0]

rows = []
for t in TS:
    T = mpf(t)
    direct = 1 - (1 - T) ** (mpf(5) / 3) - 5 * T / 6 * (1 + (1 - T) ** (mpf(2) / 3))
    s = cbrt(1 - T)
    factored = T ** 3 * (s * s + 3 * s + 1) / (6 * (1 + s + s * s) ** 3)
    assert abs(direct - factored) <= mpf(10) ** -30 * abs(factored), (t, direct, factored)
    rows.append((t, direct))

with open(OUT, "w") as fh:
    fh.write("# Mindlin-Deresiewicz energy bracket B(t) = 1-(1-t)^(5/3) - (5t/6)(1+(1-t)^(2/3)); "
             "mpmath mp.dps = 60; scripts/traction_deresiewicz.py\n")
    fh.write("# t\tbracket\n")
    for t, b in rows:
        fh.write(f"{t!r}\t{mp.nstr(b, 25)}\n")
print(len(rows), "rows")
