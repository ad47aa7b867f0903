#!/usr/bin/env python3
"""Reference K(k) - E(k) for stickslip_traction::closed::k_minus_e, given k'^2 = 1 - k^2.

mpmath, mp.dps = 40. Inputs are f64 values (printed with repr); the reference uses the
exact binary value of each input (mpf(float) is exact) and m = 1 - k'^2 in 40 digits.
Output: crates/traction/tests/data/k_minus_e.tsv
"""
from mpmath import mp, mpf, ellipk, ellipe

mp.dps = 40
kp2s = [1.0, 0.999999, 0.99, 0.9, 0.75, 0.5, 0.25, 0.1, 0.01, 1e-3, 1e-5, 2e-6, 9.9e-7, 1e-9, 1e-14]
print("# K(k) - E(k) with k'^2 = 1 - k^2 given; mpmath mp.dps = 40; scripts/traction_k_minus_e.py")
print("# kp2\tk_minus_e")
for kp2 in kp2s:
    m = 1 - mpf(kp2)
    print(f"{kp2!r}\t{mp.nstr(ellipk(m) - ellipe(m), 20)}")
