#!/usr/bin/env python3
"""Partial slip beside tamaas (issue 20, item 3): the Cattaneo sphere solved by tamaas's
PolonskyKeerTan and by stickslip's fast solver on the same cells, outside CI.

The problem: a rigid sphere pressed on an elastic half-space (E = 1, nu = 0.5, so normal and
tangential tractions do not couple), normal load P = 1 with Hertz contact radius a = 1, a
tangential force T = 0.5 f P along x with f = 0.1, both traction components free, relative
tolerance TOL for both codes. n cells across the contact diameter (cell width h = 2a/n).

- stickslip: `fast_large cattaneo n TOL FILE` (benches/examples/fast_large.rs), which solves
  on the Hertz circle's cells with the Hertz pressure prescribed and reports its operator set-up
  and solve times apart (the process start is not timed).
- tamaas: a periodic cell of 2n x 2n cells (twice the contact diameter, `--pad 2`; tamaas is
  periodic only, and the images of the contact in the neighbouring cells change its pressure
  by a few per cent of p0 at this padding), the same cell centres, the sphere's heights; PolonskyKeerTan solves the normal and the
  tangential problem together. Its `solve` call is timed; its iterations are read from its log
  (dump frequency 1). Its error measure is its own (PolonskyKeerTan's), not ours.

Both are measured against Mindlin's closed form (stick radius a (1 - T/fP)^(1/3) and the
traction field, RMS and max over the contact cells relative to f p0, p0 = 3P/(2 pi a^2)) and
against each other cell by cell. With nu = 0.5 and free directions Mindlin's solution is not
the exact one (it neglects the coupling of the two tangential directions): the traction error
of both codes levels off near 2e-2 f p0 for that reason, while the stick radius still tends
to Mindlin's.

Install tamaas in a virtual environment (network, once):
    python3 -m venv /tmp/tamaas-venv && /tmp/tamaas-venv/bin/pip install tamaas numpy
Run (from the repository root):
    cargo build --release -p stickslip-benches --example fast_large
    /tmp/tamaas-venv/bin/python scripts/compare_tamaas_slip.py --sizes 64 128 256 512
"""

import argparse
import contextlib
import io
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

F = 0.1  # friction coefficient
A = 1.0  # contact radius
P = 1.0  # normal load
E, NU = 1.0, 0.5


def mindlin_traction(r, ratio=0.5):
    """Mindlin's x traction at radius r for T/fP = ratio (FORMULAS.md E)."""
    c = A * (1.0 - ratio) ** (1.0 / 3.0)
    q0 = 3.0 * F * P / (2.0 * np.pi * A**3)
    outer = np.sqrt(np.clip(A * A - r * r, 0.0, None))
    inner = np.where(r < c, np.sqrt(np.clip(c * c - r * r, 0.0, None)), 0.0)
    return np.where(r < A, q0 * (outer - inner), 0.0)


def errors(x, y, p, qx, qy, h, stick):
    """Stick radius (area-equivalent) and traction errors against Mindlin."""
    q0 = 3.0 * F * P / (2.0 * np.pi * A * A)
    r = np.hypot(x, y)
    d = np.hypot(qx - mindlin_traction(r), qy) / q0
    c = np.sqrt(stick.sum() * h * h / np.pi)
    c_ref = A * 0.5 ** (1.0 / 3.0)
    return {
        "stick_err_cells": (c - c_ref) / h,
        "traction_rms": float(np.sqrt(np.mean(d * d))),
        "traction_max": float(d.max()),
    }


def run_ours(binary, n, tol):
    with tempfile.NamedTemporaryFile(suffix=".f64", delete=False) as fh:
        path = fh.name
    try:
        out = subprocess.run(
            [binary, "cattaneo", str(n), repr(tol), path],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
        info = json.loads(out.strip().splitlines()[-1])
        cols = np.fromfile(path, dtype="<f8").reshape(5, -1)
    finally:
        os.unlink(path)
    return info, cols


class CaptureFd:
    """Capture tamaas's iteration log (it writes to standard error)."""

    def __enter__(self):
        sys.stdout.flush()
        self.tmp = tempfile.TemporaryFile(mode="w+b")
        sys.stderr.flush()
        self.saved = (os.dup(1), os.dup(2))
        os.dup2(self.tmp.fileno(), 1)
        os.dup2(self.tmp.fileno(), 2)
        # tamaas may also write through Python's sys.stdout
        self.py = io.StringIO()
        self.redirect = contextlib.redirect_stdout(self.py)
        self.redirect.__enter__()
        return self

    def __exit__(self, *exc):
        self.redirect.__exit__(*exc)
        sys.stdout.flush()
        sys.stderr.flush()
        for fd, saved in zip((1, 2), self.saved):
            os.dup2(saved, fd)
            os.close(saved)
        self.tmp.seek(0)
        self.text = self.tmp.read().decode(errors="replace") + self.py.getvalue()
        self.tmp.close()


def run_tamaas(n, tol, max_iter, xs, ys, pad=2):
    import tamaas as tm

    big = pad * n
    h = 2.0 * A / n
    side = big * h
    estar = E / (1.0 - NU**2)
    radius = 4.0 * estar * A**3 / (3.0 * P)  # Hertz: a^3 = 3 P R / (4 E*)
    c = (np.arange(big) + 0.5) * h - side / 2.0
    X, Y = np.meshgrid(c, c, indexing="ij")
    heights = np.ascontiguousarray(-(X * X + Y * Y) / (2.0 * radius))
    model = tm.ModelFactory.createModel(tm.model_type.surface_2d, [side, side], [big, big])
    model.E, model.nu = E, NU
    solver = tm.PolonskyKeerTan(model, heights, tol, F)
    solver.max_iter = max_iter
    solver.dump_freq = 1
    t = 0.5 * F * P
    with CaptureFd() as cap:
        t0 = time.perf_counter()
        err = solver.solve([t / side**2, 0.0, P / side**2])
        seconds = time.perf_counter() - t0
    its = [int(m.group(1)) for m in re.finditer(r"^\s*(\d+)\s+\S+\s+\S+\s*$", cap.text, re.M)]
    tr = np.array(model["traction"])
    # Our elements' cells in tamaas's lattice.
    i = np.rint((xs + side / 2.0) / h - 0.5).astype(int)
    j = np.rint((ys + side / 2.0) / h - 0.5).astype(int)
    qx, qy, p = tr[i, j, 0], tr[i, j, 1], tr[i, j, 2]
    full_p = tr[..., 2]
    full_q = np.hypot(tr[..., 0], tr[..., 1])
    stick = (full_p > 0) & (full_q < F * full_p * (1.0 - 1e-9))
    info = {
        "code": "tamaas",
        "n": n,
        "cells": big * big,
        "solve_s": seconds,
        "iterations": max(its) if its else None,
        "error": float(err),
        "converged": float(err) <= tol,
    }
    info.update(errors(xs, ys, p, qx, qy, h, stick))
    return info, (p, qx, qy)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[64, 128, 256, 512])
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--max-iter", type=int, default=1000, help="tamaas iteration cap")
    ap.add_argument(
        "--pad", type=int, default=2, help="tamaas's periodic cell in contact diameters"
    )
    ap.add_argument(
        "--binary", default="target/release/examples/fast_large", help="stickslip example"
    )
    args = ap.parse_args()
    try:
        import tamaas

        version = tamaas.__version__
    except ImportError:
        sys.exit("tamaas is not installed here: see the docstring for the venv command")
    print(f"tamaas {version}, numpy {np.__version__}, tol {args.tol:g}, "
          f"tamaas cap {args.max_iter} iterations, periodic cell {args.pad} diameters, "
          f"OMP_NUM_THREADS="
          f"{os.environ.get('OMP_NUM_THREADS', 'unset')}")
    print()
    print("| n across | code | cells | solve time | iterations | final residual "
          "| stick radius error (cells) | traction RMS / f p0 | traction max / f p0 "
          "| peak memory |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for n in args.sizes:
        ours, cols = run_ours(args.binary, n, args.tol)
        x, y, p, qx, qy = cols
        h = 2.0 * A / n
        print(
            f"| {n} | stickslip fast | {ours['elements']} | {ours['solve_s']:.3g} s "
            f"(+ set-up {ours['setup_s']:.2g} s) | {ours['newton']} Newton, {ours['cg']} CG "
            f"| {ours['residual']:.1e} | {ours['stick_err_cells']:+.2f} "
            f"| {ours['traction_rms']:.2e} | {ours['traction_max']:.2e} "
            f"| {ours['peak_mib']} MiB |",
            flush=True,
        )
        tam, (tp, tqx, tqy) = run_tamaas(n, args.tol, args.max_iter, x, y, args.pad)
        conv = "" if tam["converged"] else " (cap, not converged)"
        print(
            f"| {n} | tamaas PolonskyKeerTan | {tam['cells']} | {tam['solve_s']:.3g} s "
            f"| {tam['iterations']}{conv} | {tam['error']:.1e} "
            f"| {tam['stick_err_cells']:+.2f} | {tam['traction_rms']:.2e} "
            f"| {tam['traction_max']:.2e} | - |",
            flush=True,
        )
        q0 = 3.0 * F * P / (2.0 * np.pi * A * A)
        dq = np.hypot(qx - tqx, qy - tqy) / q0
        dp = np.abs(p - tp) / (3.0 * P / (2.0 * np.pi * A * A))
        print(
            f"|  | difference | | | | | | {np.sqrt(np.mean(dq * dq)):.2e} "
            f"| {dq.max():.2e} | pressure max {dp.max():.1e} p0 |",
            flush=True,
        )


if __name__ == "__main__":
    main()
