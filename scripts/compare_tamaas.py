#!/usr/bin/env python3
"""Our periodic normal-contact solver beside tamaas on one rough surface (not run in CI).

One self-affine rough surface is generated here with numpy (Hurst exponent H, power
spectrum ~ k^(-2(1+H)) between k_low and k_high cycles per period, random phases from a
fixed seed, scaled to a given rms height) and written to heights.npy (float64, one row per
y). Both programs solve the same periodic problem on it: a rigid rough surface pressed on
an elastic half-space (E, nu) at the same mean pressure. Ours runs through the `stickslip`
CLI (a scene with geometry.kind = "surface", boundary = "periodic", profile "flat" and the
heights file as roughness); tamaas (`pip install tamaas`) through PolonskyKeerRey with the
same tolerance. Both use the periodic half-space transfer 2/(E*|q|), so the pressure fields
should agree to about the tolerance.

Printed: contact area (fraction of the period), mean gap over the period, iterations,
wall time of the solve, the solver's own residual, and the relative difference of the
pressure fields ||p_ours - p_tamaas||_2 / ||p_tamaas||_2 (and the max difference over the
max pressure).

Usage (tamaas in a venv, outside CI):
    python3 -m venv .peers && .peers/bin/pip install tamaas numpy
    cargo build --release -p stickslip
    .peers/bin/python scripts/compare_tamaas.py [--n 512] [--tol 1e-8] [--bin target/release/stickslip]
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np


def rough_surface(n, hurst, rms, k_low, k_high, seed):
    """Self-affine periodic heights (n x n, metres, zero mean, rms height `rms`)."""
    rng = np.random.default_rng(seed)
    k = np.fft.fftfreq(n, d=1.0 / n)  # cycles per period
    kx, ky = np.meshgrid(k, k)  # [j, i]: row j is y
    kk = np.hypot(kx, ky)
    amp = np.zeros_like(kk)
    band = (kk >= k_low) & (kk <= k_high)
    amp[band] = kk[band] ** (-(1.0 + hurst))
    phase = np.exp(2j * np.pi * rng.random((n, n)))
    h = np.fft.ifft2(amp * phase).real
    h -= h.mean()
    return h * (rms / h.std())


def run_ours(binary, work, n, size, e, nu, force, tol, extra=""):
    """Our CLI on heights.npy in `work`; `extra` is appended to the scene (a table)."""
    scene = f"""title = "tamaas comparison: periodic rough surface, {n} x {n}"
[geometry]
kind = "surface"
boundary = "periodic"
size = [{size}, {size}]
cells = [{n}, {n}]
[geometry.profile]
shape = "flat"
[geometry.roughness]
file = "heights.npy"
unit = "m"
[substrate]
model = "homogeneous"
e = {e}
nu = {nu}
[indenter]
model = "rigid"
[load]
normal = {force}
[solver]
tolerance = {tol}
[outputs]
surface = true
{extra}"""
    path = os.path.join(work, "scene.toml")
    with open(path, "w") as f:
        f.write(scene)
    out = os.path.join(work, "ours")
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([binary, "run", path, "--out", out, "--force", "--quiet"], check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    # CPU time (user + system) of the whole run, start-up and writing included
    cpu = (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)
    with open(os.path.join(out, "result.json")) as f:
        res = json.load(f)
    p = np.array(res["surface"]["p"], dtype=float)  # p[i][j] at (x[i], y[j])
    gap = np.array(res["surface"]["gap"], dtype=float)
    normal = res["solver"]["normal"]
    its = normal["iterations"]
    resid = normal["residual"]
    return {
        "p": p.T,  # to [j, i] like the heights
        "gap": gap.T,
        "fraction": res["contact"]["fraction"],
        "iterations": its,
        "residual": resid,
        "solve_seconds": normal["solve_seconds"] + normal["setup_seconds"],
        "wall": wall,
        "cpu": cpu,
        "plastic_fraction": res["contact"].get("plastic_fraction"),
    }


def solve_logged(solver, target, log_path=None):
    """Run a tamaas solver at `target` (a mean pressure, or a mean gap for a gap-primal
    solver) with its iteration log (printed on the C stdout and stderr) captured.

    Returns (error, solve seconds, iterations or None, log text, CPU seconds); the number of
    passes is the count of header lines in the log text. The error is
    the last one the log prints (its third column), because some solvers' `solve` returns
    0.0 whatever they reached (KatoSaturated in tamaas 2.9.0 does); the value `solve`
    returns is used only when the log has no iteration rows. With `log_path` the log goes
    to that file (kept, so that it survives a killed run) instead of a temporary one."""
    log = open(log_path, "w+") if log_path else tempfile.TemporaryFile(mode="w+")
    sys.stdout.flush()
    sys.stderr.flush()
    saved = (os.dup(1), os.dup(2))
    os.dup2(log.fileno(), 1)
    os.dup2(log.fileno(), 2)
    try:
        t0, c0 = time.perf_counter(), time.process_time()
        returned = solver.solve(target)
        secs, cpu = time.perf_counter() - t0, time.process_time() - c0
    finally:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        os.close(saved[0])
        os.close(saved[1])
    log.seek(0)
    text = log.read()
    log.close()
    # The log may hold several passes, each with its header and a count from 0:
    # KatoSaturated in tamaas 2.9.0 starts a new pass when it reaches max_iter without
    # converging (seen at 512 x 512: 5001 iterations, then 4664 more). The iterations
    # returned are the sum of the passes' last counts.
    passes, rows = [], []
    for line in text.splitlines():
        cols = line.split()
        if cols and cols[0] == "Iter":
            passes.append(None)
        elif cols and cols[0].isdigit():
            rows.append(cols)
            if passes:
                passes[-1] = int(cols[0])
            else:
                passes.append(int(cols[0]))
    error = float(rows[-1][2]) if rows and len(rows[-1]) > 2 else float(returned)
    counts = [c for c in passes if c is not None]
    return error, secs, (sum(counts) if counts else None), text, cpu


def run_tamaas(h, size, e, nu, mean_pressure, tol):
    import tamaas as tm

    n = h.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [size, size], [n, n])
    model.E = e
    model.nu = nu
    solver = tm.PolonskyKeerRey(model, np.ascontiguousarray(h), tol)
    solver.max_iter = 10000
    # tamaas prints its iteration log on the C stdout: captured to read the count
    error, secs, its, _, _ = solve_logged(solver, mean_pressure)
    p = np.array(model.traction, dtype=float).reshape(n, n)
    # gap: u - h up to the constant that closes it where there is pressure, sign so that it
    # is non-negative outside the contact
    g = np.array(model.displacement, dtype=float).reshape(n, n) - h
    g -= g[p > 0].mean()
    if g.mean() < 0:
        g = -g
    return {
        "p": p,
        "gap": g,
        "fraction": float(np.mean(p > 0)),
        "iterations": its,
        "residual": error,
        "solve_seconds": secs,
        "version": tm.__version__,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=512)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--bin", default="target/release/stickslip")
    ap.add_argument("--seed", type=int, default=7)
    args = ap.parse_args()
    n, size, e, nu = args.n, 1e-3, 210e9, 0.3
    rms, hurst = 1e-6, 0.8
    h = rough_surface(n, hurst, rms, k_low=2, k_high=n // 8, seed=args.seed)
    e_star = e / (1 - nu * nu)
    # mean pressure: 1 % of the mean slope times E* gives a few per cent of contact
    slope = np.sqrt(np.mean(np.gradient(h, size / n, axis=1) ** 2 + np.gradient(h, size / n, axis=0) ** 2))
    mean_pressure = 0.02 * slope * e_star
    force = mean_pressure * size * size
    work = tempfile.mkdtemp(prefix="compare_tamaas_")
    np.save(os.path.join(work, "heights.npy"), h)
    ours = run_ours(os.path.abspath(args.bin), work, n, size, e, nu, force, args.tol)
    try:
        tam = run_tamaas(h, size, e, nu, mean_pressure, args.tol)
    except ImportError:
        print("tamaas is not installed: pip install tamaas (see the docstring)", file=sys.stderr)
        return 2
    diff = np.linalg.norm(ours["p"] - tam["p"]) / np.linalg.norm(tam["p"])
    dmax = np.max(np.abs(ours["p"] - tam["p"])) / np.max(tam["p"])
    print(f"periodic rough surface {n} x {n}, H = {hurst}, rms {rms:g} m, rms slope {slope:.4f}, "
          f"mean pressure {mean_pressure:.4e} Pa, tolerance {args.tol:g}, tamaas {tam['version']}")
    print(f"{'':24}{'stickslip':>22}{'tamaas':>22}")
    print(f"{'contact fraction':24}{ours['fraction']:>22.6f}{tam['fraction']:>22.6f}")
    print(f"{'mean gap (m)':24}{ours['gap'].mean():>22.6e}{tam['gap'].mean():>22.6e}")
    print(f"{'iterations':24}{ours['iterations']!s:>22}{tam['iterations']!s:>22}")
    print(f"{'solve time (s)':24}{ours['solve_seconds']:>22.3f}{tam['solve_seconds']:>22.3f}")
    print(f"{'residual':24}{ours['residual']:>22.3e}{tam['residual']:>22.3e}")
    print("(residuals: ours the largest of the gap, complementarity and force residuals of docs/SCENES.md;"
          " tamaas its PolonskyKeerRey error)")
    print(f"pressure fields: ||p_ours - p_tamaas|| / ||p_tamaas|| = {diff:.3e}; "
          f"max |dp| / max p = {dmax:.3e}")
    print(f"(our run's wall time including start-up and writing the outputs: {ours['wall']:.3f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
