#!/usr/bin/env python3
"""Deep-zoom speed of `ugnis escape` against Fractalshades (its perturbation Mandelbrot and
Burning Ship with bilinear approximation), same view, size and iterations, on the same threads.
Neither side detects the interior early (Fractalshades' `interior_detect` is off, its default;
ugnis has none in deep zoom): interior pixels run to the iteration limit on both.

Fractalshades' Burning Ship iterates y ← 2|xy| − b, the mirror image of ugnis'
(|Re z| + i|Im z|)² + c: its view is given the negated imaginary part.

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

# A preperiodic point of the Burning Ship (0 → c → … lands on a repelling fixed point after
# four steps), from Newton's method to 205 digits: its structure repeats at every depth.
SHIP_X = ("-1.135970435068669382740841251730673933311924870876766725685875127621889688"
          "767121405072274975276750023921156479446428973090212757396385213938417834756"
          "849637107266137647023656531165227992031188066647728934534")
SHIP_Y = ("-0.620043386399648200978028882876077721013041924053031614563946013305331487"
          "942996783102213960061646547603087438578052911231800480602098334794794166210"
          "898372624575163846941793646094380205244377968751786864654")

VIEWS = [
    # name, x, y, width, max_iter, kind
    (
        "seahorse 1e-25",
        "-0.743643887037158704752191506114774",
        "0.131825904205311970493132056385139",
        "1e-25",
        30000,
        "mandelbrot",
    ),
    ("misiurewicz i 1e-100", "0", "1", "1e-100", 5000, "mandelbrot"),
    ("misiurewicz i 1e-1000", "0", "1", "1e-1000", 20000, "mandelbrot"),
    ("burning ship 1e-100", SHIP_X, SHIP_Y, "1e-100", 5000, "burning-ship"),
]

FS_SCRIPT = r"""
import os, sys, time, tempfile
os.environ.setdefault("NUMBA_NUM_THREADS", sys.argv[6])
import mpmath
import fractalshades as fs
import fractalshades.models as fsm

x, y, dx, max_iter, size = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
ship = sys.argv[7] == "burning-ship"
if ship:
    y = y[1:] if y.startswith("-") else "-" + y
nx, ny = (int(v) for v in size.split("x"))
digits = max(20, int(-mpmath.log10(mpmath.mpf(dx))) + 10)
times = []
for run in range(2):
    d = tempfile.mkdtemp()
    if ship:
        f = fsm.Perturbation_burning_ship(d, flavor="Burning ship")
        f.zoom(precision=digits, x=x, y=y, dx=dx, nx=nx, xy_ratio=nx / ny, theta_deg=0.0)
        f.calc_std_div(calc_name="bench", subset=None, max_iter=max_iter, M_divergence=256.0,
                       calc_hessian=False)
    else:
        f = fsm.Perturbation_mandelbrot(d)
        f.zoom(precision=digits, x=x, y=y, dx=dx, nx=nx, xy_ratio=nx / ny, theta_deg=0.0)
        f.calc_std_div(calc_name="bench", subset=None, max_iter=max_iter, M_divergence=256.0,
                       epsilon_stationnary=1e-3, calc_dzndc=False)
    t, p = time.time(), time.process_time()
    f.calc_raw("bench")
    times.append((time.time() - t, time.process_time() - p))
print(times[1][0], times[1][1])
"""


def time_ugnis(exe, view, size, threads, tolerance=None):
    name, x, y, width, max_iter, kind = view
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "deep.png")
        cmd = [exe, "escape", kind, "--center", f"{x},{y}", "--width", width,
               "--size", size, "--max-iter", str(max_iter), "--threads", str(threads),
               "-o", out]
        if tolerance is not None:
            cmd += ["--bla-tolerance", str(tolerance)]
        t, before = time.time(), os.times()
        r = subprocess.run(cmd, capture_output=True, text=True)
        dt, after = time.time() - t, os.times()
        if r.returncode != 0:
            return None, r.stderr.strip()
        cpu = (after.children_user - before.children_user
               + after.children_system - before.children_system)
        return (dt, cpu), ""


def time_fractalshades(py, view, size, threads):
    name, x, y, width, max_iter, kind = view
    # Fractalshades' dx is the view's width.
    r = subprocess.run([py, "-c", FS_SCRIPT, x, y, width, str(max_iter), size, str(threads),
                        kind],
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
    ap.add_argument("--fs-tolerance", action="store_true",
                    help="also time ugnis with Fractalshades' bilinear tolerance (1e-6, "
                         "--bla-tolerance): the same skipping, less exact than ugnis' default")
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
        if a.fs_tolerance:
            te, err = time_ugnis(a.ugnis, v, a.size, a.threads, 1e-6)
            if te is None:
                print(f"  ugnis --bla-tolerance 1e-6 failed: {err}", file=sys.stderr)
                continue
            cols = [f"{te[0]:.2f}", f"{te[0] / tf[0]:.2f}" if tf else "-", f"{te[1]:.2f}",
                    f"{te[1] / tf[1]:.2f}" if tf else "-"]
            print(f"{'  at tolerance 1e-6':24} {a.size:>8} {v[4]:>6} {cols[0]:>9} {'':>16} "
                  f"{cols[1]:>6} {cols[2]:>7} {'':>9} {cols[3]:>6}", flush=True)


if __name__ == "__main__":
    main()
