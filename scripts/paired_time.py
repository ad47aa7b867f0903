#!/usr/bin/env python3
"""Time whole processes in pairs: a command A against a baseline B, taken in turns.

    python3 scripts/paired_time.py -n 5 --vs "B command" -- A command ...
    python3 scripts/paired_time.py -n 5 -- A command ...          # A alone

Each run goes through GNU time (`/usr/bin/time`, Debian package `time`), which reports the
wall time, the user and system CPU time and the peak resident memory of the process. One
warm-up run of each command comes first and is not counted; then A and B alternate, so a
change in the machine's load hits both alike. Prints, per command, the median and the range
of wall, CPU (user + system) and peak memory, and with --vs the ratios A/B of the pairs
(median and range). On a shared machine quote the medians and the ratios, not single
times; a wide range says the machine was noisy.

This is how the "whole process" and "paired" figures in docs/ were taken (outside CI).
"""

import argparse
import shlex
import statistics
import subprocess
import sys
import tempfile

TIME = "/usr/bin/time"


def run(cmd):
    """One run of `cmd` (a shell command line): (wall s, cpu s, peak MiB, exit code)."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as out:
        argv = [TIME, "-f", "%e %U %S %M", "-o", out.name, "sh", "-c", cmd]
        code = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        fields = out.read().split()[-4:]
    wall, user, sys_, kib = (float(v) for v in fields)
    return wall, user + sys_, kib / 1024.0, code


def summary(name, runs):
    for i, label in enumerate(["wall s", "cpu s", "peak MiB"]):
        vals = [r[i] for r in runs]
        print(f"{name:>2} {label:>8}: median {statistics.median(vals):.4g}"
              f"  [{min(vals):.4g} .. {max(vals):.4g}]")
    codes = sorted({r[3] for r in runs})
    if codes != [0]:
        print(f"{name:>2} exit codes: {codes}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=5, help="counted runs of each command")
    ap.add_argument("--vs", help="the baseline command B (a shell command line)")
    ap.add_argument("command", nargs=argparse.REMAINDER, help="-- the command A")
    args = ap.parse_args()
    cmd = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not cmd or args.n < 1:
        ap.error("give -n >= 1 and a command after --")
    a = " ".join(shlex.quote(c) for c in cmd) if len(cmd) > 1 else cmd[0]
    run(a)
    if args.vs:
        run(args.vs)
    ra, rb = [], []
    for _ in range(args.n):
        ra.append(run(a))
        if args.vs:
            rb.append(run(args.vs))
    summary("A", ra)
    if args.vs:
        summary("B", rb)
        for i, label in enumerate(["wall", "cpu", "peak"]):
            ratios = [x[i] / y[i] for x, y in zip(ra, rb) if y[i] > 0]
            if ratios:
                print(f"A/B {label:>5}: median {statistics.median(ratios):.3f}"
                      f"  [{min(ratios):.3f} .. {max(ratios):.3f}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
