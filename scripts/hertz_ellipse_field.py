#!/usr/bin/env python3
"""Generate crates/halfspace/src/hertz/ellipse_field_terms.rs (stickslip-halfspace).

The stresses under the elliptic Hertz density p0 sqrt(1 - x^2/a^2 - y^2/b^2), acting either
as a normal pressure or as a shear along +x, written as one integral over the ellipsoidal
coordinate s from lambda(x, y, z) to infinity plus terms at s = lambda (docs/book, "Subsurface
fields"; Love 1929, Johnson Contact Mechanics §3.5, §3.6).

1. Love's representation (Johnson §3.2): with F1 = int int q_x Omega, H1 = int int p Omega,
   Omega = z ln(rho + z) - rho, the displacements are
     4 pi G u_x = 2 F_z + 2 nu psi1_x - z psi_x - H_x, ... (functions below, `tang`, `norm`)
   and the stresses follow by Hooke's law. Checked here for a point force against the
   Cerruti and Boussinesq kernels of crates/halfspace/src/point_load.rs.
2. For the Hertz density, V = int int q / rho dA = (pi a b / 2) int_lambda^inf
   (1 - x^2/(a^2+s) - y^2/(b^2+s) - z^2/s) ds / sqrt((a^2+s)(b^2+s)s). With
   W(s)^2 = s (1 - x^2/(a^2+s) - y^2/(b^2+s)), the twice z-integrated potential is
     Phi = (pi a b / 2) int_lambda^inf P(W, z) ds / (s sqrt(Delta)),
     P = int_z^W (z' - z)(W^2 - z'^2) dz' = (W - z)^3 (3W + z) / 12,
   which has Phi_zz = V (it differs from F1 by terms linear in z that no stress sees).
3. Each derivative of Phi is taken under the integral (Leibniz: the term at s = lambda uses
   W(lambda) = z and the implicit derivatives of lambda), summed into one integrand J and one
   boundary term B per stress component, then emitted as Rust after common-subexpression
   elimination.
Exact symbolic algebra (sympy); no floating point enters the generated expressions.
Run: python3 scripts/hertz_ellipse_field.py > crates/halfspace/src/hertz/ellipse_field_terms.rs
"""
import re

import sympy as sp

x, y, z, nu, s, a, b, zp = sp.symbols("x y z nu s a b zp", real=True)
X = [x, y, z]
L = sp.Function("L")(x, y, z)
W = sp.Function("W")(x, y)
f = sp.Function("f")(x, y, z)
G = sp.Rational(1, 2)
c = 1 / (4 * sp.pi * G)


def stresses(u):
    lam = 2 * G * nu / (1 - 2 * nu)
    e = lambda i, j: (sp.diff(u[i], X[j]) + sp.diff(u[j], X[i])) / 2
    tr = e(0, 0) + e(1, 1) + e(2, 2)
    st = lambda i, j: lam * tr * (1 if i == j else 0) + 2 * G * e(i, j)
    return [sp.expand(st(i, j)) for i, j in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)]]


def tang(F1):
    F = sp.diff(F1, z)
    psi1, psi = sp.diff(F1, x), sp.diff(F, x)
    return [
        c * (2 * sp.diff(F, z) + 2 * nu * sp.diff(psi1, x) - z * sp.diff(psi, x)),
        c * (2 * nu * sp.diff(psi1, y) - z * sp.diff(psi, y)),
        c * ((1 - 2 * nu) * psi - z * sp.diff(psi, z)),
    ]


def norm(H1):
    H = sp.diff(H1, z)
    psi = sp.diff(H, z)
    return [
        c * (-sp.diff(H, x) + 2 * nu * sp.diff(H, x) - z * sp.diff(psi, x)),
        c * (-sp.diff(H, y) + 2 * nu * sp.diff(H, y) - z * sp.diff(psi, y)),
        c * (sp.diff(H, z) + (1 - 2 * nu) * psi - z * sp.diff(psi, z)),
    ]


def point_force_check():
    R = sp.sqrt(x**2 + y**2 + z**2)
    om = z * sp.log(R + z) - R
    vals = {x: sp.Rational(3, 10), y: sp.Rational(-7, 10), z: sp.Rational(9, 20), nu: sp.Rational(27, 100)}
    st = [sp.N(v.subs(vals), 20) for v in stresses(tang(om))]
    r2 = x**2 + y**2 + z**2
    r = sp.sqrt(r2)
    r5 = r2**2 * r
    k = 1 / (2 * sp.pi)
    A = 1 - 2 * nu
    c1 = 1 / (r2 * r * (r + z) ** 2) + 2 / (r2 * (r + z) ** 3)
    cer = [
        k * (-3 * x**3 / r5 + A * (x / r**3 - 3 * x / (r * (r + z) ** 2) + x**3 * c1)),
        k * (-3 * x * y * y / r5 + A * (x / r**3 - x / (r * (r + z) ** 2) + x * y * y * c1)),
        -3 * k * x * z * z / r5,
    ]
    for got, want in zip(st, cer):
        assert abs(got - sp.N(want.subs(vals), 20)) < 1e-15, (got, want)
    stn = [sp.N(v.subs(vals), 20) for v in stresses(norm(om))]
    bz = -3 * k * z**3 / r5
    assert abs(stn[2] - sp.N(bz.subs(vals), 20)) < 1e-15


point_force_check()
P = sp.factor(sp.integrate((zp - z) * (W**2 - zp**2), (zp, z, W)))
J0 = sp.pi * a * b / 2 * P / (s * sp.sqrt((a**2 + s) * (b**2 + s) * s))
gL = -(x**2 / (a**2 + L) ** 2 + y**2 / (b**2 + L) ** 2 + z**2 / L**2)
Lsub = {
    sp.Derivative(L, x): -(2 * x / (a**2 + L)) / gL,
    sp.Derivative(L, y): -(2 * y / (b**2 + L)) / gL,
    sp.Derivative(L, z): -(2 * z / L) / gL,
}
Wsub = {sp.Derivative(W, x): -x * s / ((a**2 + s) * W), sp.Derivative(W, y): -y * s / ((b**2 + s) * W)}
cache = {(0, 0, 0): (J0, sp.Integer(0))}


def D(al):
    if al in cache:
        return cache[al]
    i = [k for k in range(3) if al[k] > 0][-1]
    prev = list(al)
    prev[i] -= 1
    J, B = D(tuple(prev))
    v = X[i]
    Jn = sp.diff(J, v).subs(Wsub)
    Bn = (sp.diff(B, v) - J.subs(s, L).subs(W, z) * sp.diff(L, v)).subs(Lsub)
    cache[al] = (Jn, Bn)
    return cache[al]


def rep(e):
    Jt, Bt = 0, 0
    for term in sp.Add.make_args(sp.expand(e)):
        (d,) = term.atoms(sp.Derivative)
        al = [0, 0, 0]
        for v, n in d.variable_count:
            al[X.index(v)] += n
        J, B = D(tuple(al))
        Jt += (term / d) * J
        Bt += (term / d) * B
    return Jt, Bt


res = {"normal": [rep(e) for e in stresses(norm(f))], "shear": [rep(e) for e in stresses(tang(f))]}
lam_s, w_s = sp.symbols("lam w")


def floats(code):
    """C code (sympy's C printer parenthesises reliably) with integer literals as f64."""
    return re.sub(r"(?<![\w.])(\d+)(?![\w.])", r"\1.0", code)


def emit(name, args, exprs, doc):
    repl, red = sp.cse(exprs, symbols=sp.numbered_symbols("t"))
    print(f"/// {doc}")
    print("#[allow(clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]")
    print(f"pub(super) fn {name}({', '.join(a_ + ': f64' for a_ in args)}) -> [f64; 6] {{")
    for sym, ex in repl:
        print(f"    let {sym} = {floats(sp.ccode(ex))};")
    print("    [" + ", ".join(floats(sp.ccode(e)) for e in red) + "]")
    print("}")
    print()


print("// @generated by scripts/hertz_ellipse_field.py: do not edit by hand.")
print("//! Integrands and end terms of the elliptic Hertz field (module docs of")
print("//! `ellipse_field`); components in the order xx, yy, zz, xy, xz, yz.")
print("use std::f64::consts::{FRAC_1_PI as M_1_PI, PI as M_PI};")
print()
print("/// `pow` of the C printer: integral exponents by repeated multiplication.")
print("fn pow(x: f64, n: f64) -> f64 {")
print("    if n == n.trunc() && n.abs() < 64.0 {")
print("        x.powi(n as i32)")
print("    } else {")
print("        x.powf(n)")
print("    }")
print("}")
print()
print("fn sqrt(x: f64) -> f64 {")
print("    x.sqrt()")
print("}")
print()
for kind in ("normal", "shear"):
    Js = [J.subs(W, w_s) for J, _ in res[kind]]
    Bs = [B.subs(L, lam_s) for _, B in res[kind]]
    emit(f"{kind}_integrand", ["s", "w", "x", "y", "z", "a", "b", "nu"], Js,
         f"Integrand over s of the {kind} load's stresses, unit amplitude; `w` is W(s).")
    emit(f"{kind}_end", ["lam", "x", "y", "z", "a", "b", "nu"], Bs,
         f"Terms at s = lambda of the {kind} load's stresses, unit amplitude.")
