#!/usr/bin/env python3
"""Our Maugis-Dugdale adhesion beside tamaas's MaugisAdhesionFunctional on one rough surface
(not run in CI; its numbers are in docs/peers.md).

The periodic surface of scripts/compare_tamaas.py (its generator), 1 mm period, pressed by a
rigid body on a soft elastic half-space (E = 1 MPa, nu = 0.5 unless given) with a
Maugis-Dugdale interface of work w and range h0 (cohesive stress w / h0 wherever the gap is
below h0). Ours: `NormalProblem::solve_adhesive` under approach control, through the bench
example normal_probe (`gap=` the heights written here, `adhesion=W,R`, `approach=D`); it
writes its pressure and gap. Tamaas: `PolonskyKeerRey` with the gap as primal variable and
constraint, with a `MaugisAdhesionFunctional` term of the same w and h0 (tamaas's way of
posing adhesion; its `BeckTeboulle` is a frictional solver that refuses this model),
solved for the mean gap that our solution has (tamaas poses the approach by the mean gap),
so both solve the same state. Both use the periodic half-space transfer 2/(E*|q|).

Adhesive problems have several solutions at one approach (the branches of the hysteresis):
ours is the one reached from no zone (the approach from far), tamaas's the one its
iteration reaches from its start; a difference of branch shows as a different contact and
force, which the script prints rather than hides.

Printed: mean pressure (negative = pulling), mean gap, contact fraction, zone fraction
(gap < h0), iterations, solve and CPU time, residuals, ||p_ours - p_tamaas|| / ||p_tamaas||,
the cells whose contact state differs, and the load average around tamaas's solve.

Usage (tamaas in a venv, outside CI):
    python3 -m venv .peers && .peers/bin/pip install tamaas numpy
    cargo build --release -p stickslip-benches --example normal_probe
    .peers/bin/python scripts/compare_tamaas_adhesion.py [--n 256] [--work 0.05] [--range 2e-6]
"""

import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_tamaas import rough_surface, solve_logged  # noqa: E402


def run_ours(binary, work_dir, gap, e, nu, w, h0, approach, tol):
    n = gap.shape[0]
    gfile = os.path.join(work_dir, "gap.f64")
    gap.astype("<f8").tofile(gfile)
    pfile = os.path.join(work_dir, "pressure.f64")
    gout = os.path.join(work_dir, "gap_out.f64")
    cmd = [binary, "rough", str(n), f"gap={gfile}", f"young={e}", f"poisson={nu}",
           f"approach={approach}", f"adhesion={w},{h0}", f"tol={tol}",
           f"pressure={pfile}", f"gapout={gout}"]
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = np.fromfile(pfile, dtype="<f8").reshape(n, n)
    g = np.fromfile(gout, dtype="<f8").reshape(n, n)

    def field(pattern):
        m = re.search(pattern, out)
        return m.group(1) if m else None

    return {
        "p": p, "gap": g, "wall": wall, "log": out.strip(),
        "cpu_process": (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime),
        # the example's own timing of the solve and its iteration counts
        "solve_seconds": field(r"solve ([0-9.]+) s \(wall"),
        "iterations": field(r"fine (\d+) iterations"),
        "zone_updates": field(r"(\d+) zone updates"),
        "residuals": field(r"residuals (gap [^;]+);"),
    }


def run_tamaas(h, size, e, nu, w, h0, mean_gap, tol, max_iter, log_path):
    """tamaas's PolonskyKeerRey with the gap as primal variable and as constraint, plus a
    MaugisAdhesionFunctional term (cohesive stress w / h0 where the gap is below h0),
    solved for the mean gap. (BeckTeboulle, which this script first used, is a frictional
    Kato-family solver: tamaas 2.9.0 refuses it on a basic_2d model, "Model type is not
    compatible with Kato solver", and its `solve` takes a mean traction, not a gap.)"""
    import tamaas as tm

    n = h.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [size, size], [n, n])
    model.E = e
    model.nu = nu
    surface = np.ascontiguousarray(h)
    solver = tm.PolonskyKeerRey(model, surface, tol, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    solver.max_iter = max_iter
    solver.dump_freq = 50
    adhesion = tm.MaugisAdhesionFunctional(surface)
    adhesion.parameters = {"rho": h0, "surface_energy": w}
    solver.addFunctionalTerm(adhesion)
    error, secs, its, text, cpu = solve_logged(solver, mean_gap, log_path)
    p = np.array(model.traction, dtype=float).reshape(n, n)
    # tamaas's displacement includes the rigid approach: its gap is u - h (checked: 0 on the
    # contact, positive outside, mean = the target)
    g = np.array(model.displacement, dtype=float).reshape(n, n) - h
    return {"p": p, "gap": g, "error": error, "iterations": its, "seconds": secs, "cpu": cpu,
            "log_tail": "\n".join(text.splitlines()[-5:]), "version": tm.__version__}


def energy(p, gap, size, e_star, w, h0):
    """Energy of a state per period (J): the elastic energy of the pressure's non-uniform part
    on the periodic half-space (1/2 L^2 sum over q != 0 of |p_q|^2 2 / (E* |q|)) plus the
    Maugis potential -(w / h0) max(h0 - g, 0) summed over the cells. At one mean gap the
    uniform part is fixed, so of two solutions at the same mean gap the lower energy is the
    more stable one."""
    n = p.shape[0]
    k = 2.0 * np.pi * np.fft.fftfreq(n, d=size / n)
    q = np.hypot(*np.meshgrid(k, k))
    ph = np.fft.fft2(p) / (n * n)
    q[0, 0] = np.inf
    elastic = 0.5 * size * size * float(np.sum(np.abs(ph) ** 2 * 2.0 / (e_star * q)))
    adhesive = -(w / h0) * float(np.sum(np.maximum(h0 - gap, 0.0))) * (size / n) ** 2
    return elastic + adhesive


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--bin", default="target/release/examples/normal_probe")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--young", type=float, default=1e6)
    ap.add_argument("--poisson", type=float, default=0.5)
    ap.add_argument("--work", type=float, default=0.05, help="w (J/m^2)")
    ap.add_argument("--range", type=float, default=2e-6, help="h0 (m)")
    ap.add_argument("--approach", type=float, default=-1.0e-6,
                    help="approach from the first touch of the highest summit (m)")
    ap.add_argument("--max-iter", type=int, default=5000)
    ap.add_argument("--log", default=None, help="keep tamaas's iteration log in this file")
    args = ap.parse_args()
    n, size = args.n, 1e-3
    h = rough_surface(n, 0.8, 1e-6, k_low=2, k_high=n // 8, seed=args.seed)
    gap = h.max() - h
    work_dir = tempfile.mkdtemp(prefix="compare_tamaas_adhesion_")
    ours = run_ours(os.path.abspath(args.bin), work_dir, gap, args.young, args.poisson,
                    args.work, args.range, args.approach, args.tol)
    # Our mean gap at the solution, the approach as tamaas poses it.
    mean_gap = float(np.mean(ours["gap"]))
    try:
        load_before = os.getloadavg()
        tam = run_tamaas(h, size, args.young, args.poisson, args.work, args.range, mean_gap,
                         args.tol, args.max_iter, args.log)
        load_after = os.getloadavg()
    except ImportError:
        print("tamaas is not installed: pip install tamaas (see the docstring)", file=sys.stderr)
        print(ours["log"])
        return 2
    diff = np.linalg.norm(ours["p"] - tam["p"]) / np.linalg.norm(tam["p"])
    print(f"periodic rough surface {n} x {n}, E {args.young:.3e} Pa, nu {args.poisson}, "
          f"w {args.work} J/m^2, h0 {args.range:.3e} m, approach {args.approach:.3e} m "
          f"(mean gap {mean_gap:.4e} m), tamaas {tam['version']}")
    print(ours["log"])
    zone = args.range
    tg = tam["gap"]
    # in contact: a gap below 1e-6 h0 (both solvers close the gap to their tolerance only:
    # ours leaves up to about 1e-12 m on contact cells at 256 x 256, h0 = 2 um)
    closed = 1e-6 * zone
    ours_contact, tam_contact = ours["gap"] <= closed, tg <= closed
    print(f"{'':24}{'ours':>18}{'tamaas Maugis':>18}")
    print(f"{'mean pressure (Pa)':24}{ours['p'].mean():>18.6e}{tam['p'].mean():>18.6e}")
    print(f"{'mean gap (m)':24}{ours['gap'].mean():>18.6e}{tg.mean():>18.6e}")
    print(f"{'contact fraction':24}{np.mean(ours_contact):>18.6f}{np.mean(tam_contact):>18.6f}")
    print(f"{'zone fraction':24}{np.mean(ours['gap'] < zone):>18.6f}{np.mean(tg < zone):>18.6f}")
    e_star = args.young / (1 - args.poisson ** 2)
    print(f"{'energy per period (J)':24}"
          f"{energy(ours['p'], ours['gap'], size, e_star, args.work, zone):>18.9e}"
          f"{energy(tam['p'], tg, size, e_star, args.work, zone):>18.9e}")
    print(f"{'iterations':24}{ours['iterations']!s:>18}{tam['iterations']!s:>18}")
    print(f"{'zone updates':24}{ours['zone_updates']!s:>18}{'':>18}")
    print(f"{'solve time (s)':24}{ours['solve_seconds']!s:>18}{tam['seconds']:>18.3f}")
    print(f"{'CPU time (s)':24}{ours['cpu_process']:>18.3f}{tam['cpu']:>18.3f}")
    print(f"{'run wall time (s)':24}{ours['wall']:>18.3f}{'':>18}")
    print(f"{'residual':24}{ours['residuals']!s:>18}{tam['error']:>18.3e}")
    print("(solve time: ours the example's solve, tamaas its solve call; CPU time: ours the whole example "
          "process, tamaas the solve call; residual: ours gap, complementarity and force as the example "
          "prints them, tamaas the last error of its log)")
    print(f"pressure fields: ||p_ours - p_tamaas|| / ||p_tamaas|| = {diff:.3e}; "
          f"max |dp| / (w / h0) = {np.max(np.abs(ours['p'] - tam['p'])) / (args.work / zone):.3e}; "
          f"cells whose contact state differs: {int(np.sum(ours_contact != tam_contact))}, in the zone: "
          f"{int(np.sum((ours['gap'] < zone) != (tg < zone)))}")
    print(f"load average (1, 5, 15 min) before tamaas {load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, "
          f"after {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f}")
    if tam["error"] > args.tol:
        print(f"tamaas did not reach the tolerance; the end of its log:\n{tam['log_tail']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
