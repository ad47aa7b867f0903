#!/usr/bin/env python3
"""Our hardness cap beside tamaas's KatoSaturated on one rough surface (not run in CI).

The same periodic problem as scripts/compare_tamaas.py (its surface generator and its run of
our CLI, with `[interface] hardness` added): a rigid self-affine rough surface pressed on an
elastic half-space at a mean pressure, the pressure capped at the hardness H. Ours: the
normal solver with `interface.hardness` (projected CG on the box 0 <= p <= H, a secant on
the approach for the force); tamaas: `KatoSaturated(model, surface, tolerance, pmax = H)`.
Also our elastic solve of the same surface, for the cost ratio. Both use the periodic
half-space transfer 2/(E*|q|).

Printed: contact fraction, plastic share (cells at H over contact cells), iterations, solve
time, residual, and ||p_ours - p_tamaas|| / ||p_tamaas||; if tamaas does not converge, its
error and iteration count as it reports them.

Usage (tamaas in a venv, outside CI):
    python3 -m venv .peers && .peers/bin/pip install tamaas numpy
    cargo build --release -p stickslip
    .peers/bin/python scripts/compare_tamaas_hardness.py [--n 256] [--hardness-ratio 0.3]
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_tamaas import rough_surface, run_ours, solve_logged  # noqa: E402


def run_kato(h, size, e, nu, mean_pressure, hardness, tol, max_iter):
    import tamaas as tm

    n = h.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [size, size], [n, n])
    model.E = e
    model.nu = nu
    solver = tm.KatoSaturated(model, np.ascontiguousarray(h), tol, hardness)
    solver.max_iter = max_iter
    error, secs, its, text = solve_logged(solver, mean_pressure)
    p = np.array(model.traction, dtype=float).reshape(n, n)
    return {
        "p": p,
        "fraction": float(np.mean(p > 0)),
        "plastic": float(np.mean(p >= hardness * (1 - 1e-12)) / max(np.mean(p > 0), 1e-300)),
        "iterations": its,
        "residual": error,
        "solve_seconds": secs,
        "log_tail": "\n".join(text.splitlines()[-5:]),
        "version": tm.__version__,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--bin", default="target/release/stickslip")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--hardness", type=float, default=5e9, help="H (Pa)")
    ap.add_argument("--max-iter", type=int, default=5000)
    args = ap.parse_args()
    n, size, e, nu = args.n, 1e-3, 210e9, 0.3
    rms, hurst = 1e-6, 0.8
    h = rough_surface(n, hurst, rms, k_low=2, k_high=n // 8, seed=args.seed)
    e_star = e / (1 - nu * nu)
    slope = np.sqrt(np.mean(np.gradient(h, size / n, axis=1) ** 2 + np.gradient(h, size / n, axis=0) ** 2))
    mean_pressure = 0.02 * slope * e_star
    force = mean_pressure * size * size
    work = tempfile.mkdtemp(prefix="compare_tamaas_hardness_")
    np.save(os.path.join(work, "heights.npy"), h)
    binary = os.path.abspath(args.bin)
    elastic = run_ours(binary, work, n, size, e, nu, force, args.tol)
    ours = run_ours(binary, work, n, size, e, nu, force, args.tol,
                    extra=f"[interface]\nhardness = {args.hardness}\n")
    ours["plastic"] = float(np.mean(ours["p"] >= args.hardness) / np.mean(ours["p"] > 0))
    try:
        tam = run_kato(h, size, e, nu, mean_pressure, args.hardness, args.tol, args.max_iter)
    except ImportError:
        print("tamaas is not installed: pip install tamaas (see the docstring)", file=sys.stderr)
        return 2
    diff = np.linalg.norm(ours["p"] - tam["p"]) / np.linalg.norm(tam["p"])
    print(f"periodic rough surface {n} x {n}, mean pressure {mean_pressure:.4e} Pa, hardness "
          f"{args.hardness:.3e} Pa (elastic peak {elastic['p'].max():.3e} Pa), tolerance {args.tol:g}, "
          f"tamaas {tam['version']}")
    print(f"{'':24}{'ours, capped':>18}{'tamaas Kato':>18}{'ours, elastic':>18}")
    print(f"{'contact fraction':24}{ours['fraction']:>18.6f}{tam['fraction']:>18.6f}{elastic['fraction']:>18.6f}")
    print(f"{'plastic share':24}{ours['plastic']:>18.6f}{tam['plastic']:>18.6f}{'':>18}")
    print(f"{'iterations':24}{ours['iterations']!s:>18}{tam['iterations']!s:>18}{elastic['iterations']!s:>18}")
    print(f"{'solve time (s)':24}{ours['solve_seconds']:>18.3f}{tam['solve_seconds']:>18.3f}{elastic['solve_seconds']:>18.3f}")
    print(f"{'residual':24}{ours['residual']:>18.3e}{tam['residual']:>18.3e}{elastic['residual']:>18.3e}")
    print(f"pressure fields: ||p_ours - p_tamaas|| / ||p_tamaas|| = {diff:.3e}")
    if tam["residual"] > args.tol:
        print(f"tamaas did not reach the tolerance; the end of its log:\n{tam['log_tail']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
