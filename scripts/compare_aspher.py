#!/usr/bin/env python3
"""Our normal-contact solver beside ASPHER on issue 30's two problems (not run in CI).

The problems are those of the example `normal_probe` (benches/examples/normal_probe.rs,
benches/src/surfaces.rs): `rough N`, a rigid periodic band-limited self-affine surface (H =
0.8, 4 to 64 cycles per period, rms height 1 um, period 1 mm, the same continuous surface on
every lattice) on a steel half-space (E = 210 GPa, nu = 0.3) at a mean pressure of 350 MPa
(about 5 % of the period in contact); `hertz N`, a rigid sphere (R = 10 mm) on steel, free
boundary, lattice side 1 mm, the Hertz contact radius 0.3 mm. Our example writes the initial
gap (`write=FILE`, little-endian f64, row-major), so both programs solve the very same
array, at the same tolerance (1e-8 unless --tol).

Ours runs as the example (one process per solve; the time is the solver's own
`solve_seconds` including its coarser levels, plus the operator set-up printed apart).
ASPHER 0.1.3 (built from its PyPI source in a venv of your own: `pip install numpy rfgen scikit-build-core pybind11`, then `pip install --no-build-isolation --no-binary aspher aspher==0.1.3.post1`, about 4 min) runs `solve_nested` with its
defaults (nested grids from 64, |q| preconditioner) on the `periodic` backend for the rough
surface, and on the `fft` and the default `h2` backends for the free sphere; the time is
the `solve_nested` call (operators, coarse levels, finest level). Printed per solver: time,
iterations on the finest lattice and on the coarse ones, the contact fraction, and the
pressure fields' difference (relative L2 and max over max).

Usage (ASPHER in a venv, outside CI):
    cargo build --release -p stickslip-benches --example normal_probe
    OMP_NUM_THREADS=2 .aspher/bin/python scripts/compare_aspher.py rough 1024 [--repeat 5]
    OMP_NUM_THREADS=2 .aspher/bin/python scripts/compare_aspher.py hertz 1024
`--aspher-only` runs just ASPHER's solve on an existing gap file (for paired timing).
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

E, NU = 210e9, 0.3
E_STAR = E / (1.0 - NU * NU)  # rigid indenter on steel
SIDE = 1e-3


def load_of(case, n):
    if case == "rough":
        return 350e6  # mean pressure, Pa
    a, r = 0.3 * SIDE, 0.01
    force = 4.0 * E_STAR * a**3 / (3.0 * r)
    return force / SIDE**2


def run_ours(probe, case, n, tol, work):
    pfile = os.path.join(work, "p_ours.f64")
    out = subprocess.run([probe, case, str(n), f"tol={tol}", f"pressure={pfile}"],
                         check=True, capture_output=True, text=True).stdout
    solve = float(re.search(r"solve ([0-9.]+) s \(wall", out).group(1))
    setup = float(re.search(r"setup ([0-9.]+) s", out).group(1))
    fine = int(re.search(r"fine (\d+) iterations", out).group(1))
    levels = re.search(r"levels \[([^\]]*)\]", out).group(1).split()
    coarse = sum(int(l.split(":")[1].split("+")[0]) for l in levels)
    p = np.fromfile(pfile, dtype="<f8").reshape(n, n)
    return {"seconds": solve + setup, "fine": fine, "coarse": coarse, "p": p, "line": out.strip()}


def run_aspher(gap, case, n, tol, backend):
    import aspher

    t0 = time.perf_counter()
    res = aspher.solve_nested(grid_size=n, gap=gap, p_nominal=load_of(case, n), domain_size=SIDE,
                              E_star=E_STAR, tol=tol, backend=backend)
    secs = time.perf_counter() - t0
    stages = res.stage_stats
    coarse = sum(s["iterations"] for s in stages[:-1]) if len(stages) > 1 else 0
    return {"seconds": secs, "fine": res.iterations, "coarse": coarse, "status": str(res.status),
            "p": np.asarray(res.pressure, dtype=float).reshape(n, n),
            "fw": res.fw_error, "pen": res.penetration_error}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", choices=["rough", "hertz"])
    ap.add_argument("n", type=int)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--probe", default="target/release/examples/normal_probe")
    ap.add_argument("--aspher-only", metavar="GAPFILE")
    ap.add_argument("--backend", default=None)
    args = ap.parse_args()
    n = args.n
    backends = [args.backend] if args.backend else (["periodic"] if args.case == "rough" else ["fft", "h2"])
    if args.aspher_only:
        gap = np.fromfile(args.aspher_only, dtype="<f8")
        a = run_aspher(gap, args.case, n, args.tol, backends[0])
        print(f"aspher {backends[0]} {args.case} {n}: {a['seconds']:.3f} s, {a['fine']} + {a['coarse']} it, {a['status']}")
        return 0
    work = tempfile.mkdtemp(prefix="compare_aspher_")
    gfile = os.path.join(work, "gap.f64")
    subprocess.run([args.probe, args.case, str(n), f"write={gfile}"], check=True, capture_output=True)
    gap = np.fromfile(gfile, dtype="<f8")
    rows = []
    for _ in range(args.repeat):
        o = run_ours(args.probe, args.case, n, args.tol, work)
        row = {"ours": o}
        for b in backends:
            row[b] = run_aspher(gap, args.case, n, args.tol, b)
        rows.append(row)
    o = rows[-1]["ours"]
    print(f"{args.case} {n}x{n}, tolerance {args.tol:g}, {args.repeat} paired run(s); times are medians")
    print(f"  stickslip: {statistics.median(r['ours']['seconds'] for r in rows):.3f} s "
          f"(set-up + solve), {o['fine']} fine + {o['coarse']} coarse iterations, "
          f"contact {np.mean(o['p'] > 0):.4f}")
    for b in backends:
        a = rows[-1][b]
        t = statistics.median(r[b]["seconds"] for r in rows)
        ratio = statistics.median(r[b]["seconds"] / r["ours"]["seconds"] for r in rows)
        d2 = np.linalg.norm(o["p"] - a["p"]) / np.linalg.norm(a["p"])
        dm = np.max(np.abs(o["p"] - a["p"])) / np.max(a["p"])
        same = np.sum((o["p"] > 0) != (a["p"] > 0))
        print(f"  ASPHER {b}: {t:.3f} s, {a['fine']} fine + {a['coarse']} coarse iterations, {a['status']}, "
              f"contact {np.mean(a['p'] > 0):.4f} (fw {a['fw']:.1e}, penetration {a['pen']:.1e}); "
              f"ours {ratio:.2f}x faster (median of pairs); pressure difference L2 {d2:.1e}, "
              f"max {dm:.1e}, contact cells differing {same}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
