#!/usr/bin/env python3
"""Deep-zoom speed of `ugnis escape` against Fractalshades (its perturbation Mandelbrot with
bilinear approximation), same view, size and iterations, on the same threads.

Fractalshades runs each view twice in one process and its second run is timed, so that
numba's compilation does not count. It needs `pip install fractalshades gmpy2` (and Debian's
libgmp-dev libmpfr-dev libmpc-dev); give its Python with --fs-python (skipped when absent).

The correctness figure (continuous counts against an exact per-pixel computation in big
fixed point) is the test `escape::deep::tests` (`cargo test --lib escape::deep`).

    python3 benches/deep_zoom.py --ugnis target/release/ugnis --fs-python /path/to/python
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

VIEWS = [
    # name, x, y, width, max_iter
    (
        "seahorse 1e-25",
        "-0.743643887037158704752191506114774",
        "0.131825904205311970493132056385139",
        "1e-25",
        30000,
    ),
    ("misiurewicz i 1e-100", "0", "1", "1e-100", 5000),
    ("misiurewicz i 1e-1000", "0", "1", "1e-1000", 20000),
]

FS_SCRIPT = r"""
import os, sys, time, tempfile
os.environ.setdefault("NUMBA_NUM_THREADS", sys.argv[6])
import mpmath
import fractalshades as fs
import fractalshades.models as fsm

x, y, dx, max_iter, size = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
nx, ny = (int(v) for v in size.split("x"))
digits = max(20, int(-mpmath.log10(mpmath.mpf(dx))) + 10)
times = []
for run in range(2):
    d = tempfile.mkdtemp()
    f = fsm.Perturbation_mandelbrot(d)
    f.zoom(precision=digits, x=x, y=y, dx=dx, nx=nx, xy_ratio=nx / ny, theta_deg=0.0)
    f.calc_std_div(calc_name="bench", subset=None, max_iter=max_iter, M_divergence=256.0,
                   epsilon_stationnary=1e-3, calc_dzndc=False)
    t, p = time.time(), time.process_time()
    f.calc_raw("bench")
    times.append((time.time() - t, time.process_time() - p))
print(times[1][0], times[1][1])
"""


def time_ugnis(exe, view, size, threads):
    name, x, y, width, max_iter = view
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "deep.png")
        cmd = [exe, "escape", "mandelbrot", "--center", f"{x},{y}", "--width", width,
               "--size", size, "--max-iter", str(max_iter), "--threads", str(threads),
               "-o", out]
        t, before = time.time(), os.times()
        r = subprocess.run(cmd, capture_output=True, text=True)
        dt, after = time.time() - t, os.times()
        if r.returncode != 0:
            return None, r.stderr.strip()
        cpu = (after.children_user - before.children_user
               + after.children_system - before.children_system)
        return (dt, cpu), ""


def time_fractalshades(py, view, size, threads):
    name, x, y, width, max_iter = view
    # Fractalshades' dx is the view's width.
    r = subprocess.run([py, "-c", FS_SCRIPT, x, y, width, str(max_iter), size, str(threads)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip().splitlines()[-1:]
    wall, cpu = r.stdout.strip().splitlines()[-1].split()
    return (float(wall), float(cpu)), ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ugnis", default="target/release/ugnis")
    ap.add_argument("--fs-python", default=None)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default=None, help="run views whose name contains this")
    a = ap.parse_args()
    # On a machine other jobs load, wall times stretch with the load; CPU times (all threads)
    # do much less, so both are shown.
    print(f"{'view':24} {'size':>8} {'iters':>6} {'ugnis s':>9} {'Fractalshades s':>16} "
          f"{'ratio':>6} {'CPU s':>7} {'FS CPU s':>9} {'ratio':>6}")
    for v in VIEWS:
        if a.only and a.only not in v[0]:
            continue
        tu, err = time_ugnis(a.ugnis, v, a.size, a.threads)
        tf = None
        if a.fs_python:
            tf, ferr = time_fractalshades(a.fs_python, v, a.size, a.threads)
            if tf is None:
                print(f"  Fractalshades failed: {ferr}", file=sys.stderr)
        if tu is None:
            print(f"{v[0]:24} {a.size:>8} {v[4]:>6} failed: {err}", flush=True)
            continue
        cols = [f"{tu[0]:.2f}", f"{tf[0]:.2f}" if tf else "-",
                f"{tu[0] / tf[0]:.2f}" if tf else "-", f"{tu[1]:.2f}",
                f"{tf[1]:.2f}" if tf else "-", f"{tu[1] / tf[1]:.2f}" if tf else "-"]
        print(f"{v[0]:24} {a.size:>8} {v[4]:>6} {cols[0]:>9} {cols[1]:>16} {cols[2]:>6} "
              f"{cols[3]:>7} {cols[4]:>9} {cols[5]:>6}", flush=True)


if __name__ == "__main__":
    main()
