#!/usr/bin/env python3
"""Our hardness cap beside tamaas's KatoSaturated on one rough surface (not run in CI).

The same periodic problem as scripts/compare_tamaas.py (its surface generator and its run of
our CLI, with `[interface] hardness` added): a rigid self-affine rough surface pressed on an
elastic half-space at a mean pressure, the pressure capped at the hardness H. Ours: the
normal solver with `interface.hardness` (projected CG on the box 0 <= p <= H, a secant on
the approach for the force); tamaas: `KatoSaturated(model, surface, tolerance, pmax = H)`.
Also our elastic solve of the same surface, for the cost ratio. Both use the periodic
half-space transfer 2/(E*|q|).

Printed: contact fraction, plastic share (cells at H over contact cells), mean and peak
pressure, iterations, solve and CPU time, residual, ||p_ours - p_tamaas|| / ||p_tamaas||, and
the load average around the run (the times mean little on a busy machine); if tamaas does not
converge, its error and iteration count as its log reports them, and the end of its log.

Usage (tamaas in a venv, outside CI):
    python3 -m venv .peers && .peers/bin/pip install tamaas numpy
    cargo build --release -p stickslip
    .peers/bin/python scripts/compare_tamaas_hardness.py [--n 256] [--hardness 5e9] \
        [--bin target/release/stickslip] [--tamaas-units normalized|si] [--log kato.log]
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_tamaas import rough_surface, run_ours, solve_logged  # noqa: E402


def pass_counts(text):
    """The last iteration count of each pass in a tamaas log ("5001 + 530"): KatoSaturated in
    tamaas 2.9.0 logs two passes, each from iteration 0 with its own header."""
    counts = []
    for line in text.splitlines():
        cols = line.split()
        if cols[:1] == ["Iter"]:
            counts.append("-")
        elif cols and cols[0].isdigit():
            if not counts:
                counts.append("-")
            counts[-1] = cols[0]
    return " + ".join(counts)


def run_kato(h, size, e, nu, mean_pressure, hardness, tol, max_iter, units, log_path):
    """tamaas's KatoSaturated on heights `h` (m) at `mean_pressure` with the cap `hardness`.

    units = "normalized" (default): the same problem in units where the period is 1 and
    E* is 1 (heights h / L, pressures p / E*), scaled back afterwards. The problem is linear
    in that scaling (u = L / E* times the unit-cell operator on p), so the solution is the
    same; it is needed because KatoSaturated's projected-gradient step in tamaas 2.9.0 is not
    scaled by E*: in SI units (E* ~ 1e11 Pa, heights ~ 1e-6 m) it moves the pressure by
    about the gap in metres per iteration, and its error stays at its first value (seen at
    32 x 32: 2.62 for 300 iterations, the pressure left uniform). units = "si" poses it as
    given, to show that."""
    import tamaas as tm

    n = h.shape[0]
    e_star = e / (1 - nu * nu)
    if units == "si":
        length, stress = 1.0, 1.0
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [size, size], [n, n])
        model.E = e
        model.nu = nu
    else:
        length, stress = size, e_star
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
        model.E = 1.0
        model.nu = 0.0
    solver = tm.KatoSaturated(model, np.ascontiguousarray(h / length), tol, hardness / stress)
    solver.max_iter = max_iter
    solver.dump_freq = 50
    error, secs, its, text, cpu = solve_logged(solver, mean_pressure / stress, log_path)
    p = np.array(model.traction, dtype=float).reshape(n, n) * stress
    fraction = float(np.mean(p > 0))
    return {
        "p": p,
        "fraction": fraction,
        "plastic": float(np.mean(p >= hardness * (1 - 1e-9)) / max(fraction, 1e-300)),
        "iterations": its,
        "residual": error,
        "solve_seconds": secs,
        "cpu": cpu,
        "passes": pass_counts(text),
        "log_tail": "\n".join(text.splitlines()[-5:]),
        "version": tm.__version__,
    }


def run_kato_within(seconds, log_path, *args):
    """run_kato in a forked child, given `seconds` of wall time: returns its result, or None
    when the child was stopped (its log, kept in `log_path`, then tells how far it got)."""
    import multiprocessing as mp
    import pickle

    out = log_path + ".result.pkl"

    def child():
        with open(out, "wb") as f:
            pickle.dump(run_kato(*args, log_path), f)

    proc = mp.get_context("fork").Process(target=child)
    proc.start()
    proc.join(seconds)
    if proc.is_alive():
        proc.terminate()
        proc.join()
        return None
    if proc.exitcode != 0:
        raise RuntimeError(f"the tamaas child failed (exit {proc.exitcode}); see {log_path}")
    with open(out, "rb") as f:
        return pickle.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--bin", default="target/release/stickslip")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--hardness", type=float, default=5e9, help="H (Pa)")
    ap.add_argument("--max-iter", type=int, default=5000)
    ap.add_argument("--tamaas-units", choices=["normalized", "si"], default="normalized",
                    help="pose tamaas's problem with period 1 and E* 1 (default) or in SI units")
    ap.add_argument("--log", default=None, help="keep tamaas's iteration log in this file")
    ap.add_argument("--tamaas-seconds", type=float, default=None,
                    help="stop tamaas after this wall time and report how far its log got")
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
    ours["plastic"] = ours["plastic_fraction"]
    load_before = os.getloadavg()
    try:
        kato_args = (h, size, e, nu, mean_pressure, args.hardness, args.tol, args.max_iter, args.tamaas_units)
        if args.tamaas_seconds is None:
            tam = run_kato(*kato_args, args.log)
        else:
            log_path = args.log or os.path.join(work, "kato.log")
            tam = run_kato_within(args.tamaas_seconds, log_path, *kato_args)
            if tam is None:
                with open(log_path) as f:
                    text = f.read()
                rows = [r.split() for r in text.splitlines() if r.split()[:1] and r.split()[0].isdigit()]
                passes = pass_counts(text)
                print(f"{n} x {n}, mean pressure {mean_pressure:.4e} Pa, H {args.hardness:.3e} Pa: ours capped "
                      f"{ours['iterations']} iterations, solve {ours['solve_seconds']:.3f} s, CPU {ours['cpu']:.3f} s, "
                      f"contact {ours['fraction']:.6f}, plastic {ours['plastic']:.6f}, residual {ours['residual']:.3e}; "
                      f"elastic {elastic['iterations']} iterations, solve {elastic['solve_seconds']:.3f} s, "
                      f"CPU {elastic['cpu']:.3f} s")
                print(f"tamaas stopped after {args.tamaas_seconds:g} s without converging: passes {passes}, "
                      f"last logged row {' '.join(rows[-1]) if rows else 'none'}; load average now "
                      f"{os.getloadavg()[0]:.2f}; the end of its log:\n" + "\n".join(text.splitlines()[-5:]))
                return 1
    except ImportError:
        print("tamaas is not installed: pip install tamaas (see the docstring)", file=sys.stderr)
        return 2
    load_after = os.getloadavg()
    diff = np.linalg.norm(ours["p"] - tam["p"]) / np.linalg.norm(tam["p"])
    dmax = np.max(np.abs(ours["p"] - tam["p"])) / args.hardness
    print(f"periodic rough surface {n} x {n}, mean pressure {mean_pressure:.4e} Pa, hardness "
          f"{args.hardness:.3e} Pa (elastic peak {elastic['p'].max():.3e} Pa), tolerance {args.tol:g}, "
          f"tamaas {tam['version']} ({args.tamaas_units} units)")
    print(f"{'':24}{'ours, capped':>18}{'tamaas Kato':>18}{'ours, elastic':>18}")
    print(f"{'contact fraction':24}{ours['fraction']:>18.6f}{tam['fraction']:>18.6f}{elastic['fraction']:>18.6f}")
    print(f"{'plastic share':24}{ours['plastic']:>18.6f}{tam['plastic']:>18.6f}{'':>18}")
    print(f"{'mean pressure (Pa)':24}{ours['p'].mean():>18.6e}{tam['p'].mean():>18.6e}{elastic['p'].mean():>18.6e}")
    print(f"{'peak pressure (Pa)':24}{ours['p'].max():>18.6e}{tam['p'].max():>18.6e}{elastic['p'].max():>18.6e}")
    print(f"{'iterations':24}{ours['iterations']!s:>18}{tam['iterations']!s:>18}{elastic['iterations']!s:>18}")
    print(f"{'passes (tamaas)':24}{'':>18}{tam['passes']:>18}{'':>18}")
    print(f"{'solve time (s)':24}{ours['solve_seconds']:>18.3f}{tam['solve_seconds']:>18.3f}{elastic['solve_seconds']:>18.3f}")
    print(f"{'CPU time (s)':24}{ours['cpu']:>18.3f}{tam['cpu']:>18.3f}{elastic['cpu']:>18.3f}")
    print(f"{'run wall time (s)':24}{ours['wall']:>18.3f}{'':>18}{elastic['wall']:>18.3f}")
    print(f"{'residual':24}{ours['residual']:>18.3e}{tam['residual']:>18.3e}{elastic['residual']:>18.3e}")
    print("(solve time: ours setup + solve from result.json, tamaas its solve call; CPU time: ours the whole "
          "CLI run with start-up and writing, tamaas the solve call; run wall time: our whole CLI run; "
          "residuals: ours the largest of docs/SCENES.md's, tamaas the last error of its log)")
    print(f"pressure fields: ||p_ours - p_tamaas|| / ||p_tamaas|| = {diff:.3e}; max |dp| / H = {dmax:.3e}")
    print(f"load average (1, 5, 15 min) before tamaas {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
          f"after {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f}")
    if tam["residual"] > args.tol:
        print(f"tamaas did not reach the tolerance; the end of its log:\n{tam['log_tail']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
