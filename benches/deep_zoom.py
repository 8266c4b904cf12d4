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
    t = time.time()
    f.calc_raw("bench")
    times.append(time.time() - t)
print(times[1])
"""


def time_ugnis(exe, view, size, threads):
    name, x, y, width, max_iter = view
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "deep.png")
        cmd = [exe, "escape", "mandelbrot", "--center", f"{x},{y}", "--width", width,
               "--size", size, "--max-iter", str(max_iter), "--threads", str(threads),
               "-o", out]
        t = time.time()
        r = subprocess.run(cmd, capture_output=True, text=True)
        dt = time.time() - t
        if r.returncode != 0:
            return None, r.stderr.strip()
        return dt, ""


def time_fractalshades(py, view, size, threads):
    name, x, y, width, max_iter = view
    # Fractalshades' dx is the view's width.
    r = subprocess.run([py, "-c", FS_SCRIPT, x, y, width, str(max_iter), size, str(threads)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip().splitlines()[-1:]
    return float(r.stdout.strip().splitlines()[-1]), ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ugnis", default="target/release/ugnis")
    ap.add_argument("--fs-python", default=None)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default=None, help="run views whose name contains this")
    a = ap.parse_args()
    print(f"{'view':24} {'size':>8} {'iters':>6} {'ugnis s':>9} {'Fractalshades s':>16} {'ratio':>6}")
    for v in VIEWS:
        if a.only and a.only not in v[0]:
            continue
        tu, err = time_ugnis(a.ugnis, v, a.size, a.threads)
        tf = None
        if a.fs_python:
            tf, ferr = time_fractalshades(a.fs_python, v, a.size, a.threads)
            if tf is None:
                print(f"  Fractalshades failed: {ferr}", file=sys.stderr)
        ratio = f"{tu / tf:.2f}" if tu and tf else "-"
        tu_s = f"{tu:.2f}" if tu else f"failed: {err}"
        tf_s = f"{tf:.2f}" if tf else "-"
        print(f"{v[0]:24} {a.size:>8} {v[4]:>6} {tu_s:>9} {tf_s:>16} {ratio:>6}", flush=True)


if __name__ == "__main__":
    main()
