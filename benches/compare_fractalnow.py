#!/usr/bin/env python3
"""Side-by-side speed of ugnis's escape-time renderer and fractalnow.

Renders the same Mandelbrot view (centre -0.7+0i, width 3, 1920x1080, max-iter 1000, 2 threads)
with fractalnow in exact mode (-i 1: every pixel computed), with fractalnow's default
interpolated mode, and with ugnis in exact mode (every pixel computed), one after the other,
several times, and prints the median wall times and the ratios. Both write their image file
(fractalnow PPM, ugnis PNG), so the times include output.

Targets: ugnis <= 0.2x fractalnow -i 1, and faster than fractalnow's default mode.

Needs: fractalnow (Debian package) and a release build of ugnis (cargo build --release).
Also compares the pictures: the fraction of pixels both programs classify the same way
(inside / outside), which should be close to 1.

Usage: benches/compare_fractalnow.py [--runs 5] [--size 1920x1080] [--max-iter 1000]
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UGNIS = os.path.join(ROOT, "target", "release", "ugnis")


def timed(cmd):
    t = time.perf_counter()
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    dt = time.perf_counter() - t
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stderr.decode()}")
    return dt


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--max-iter", type=int, default=1000)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    if not shutil.which("fractalnow"):
        sys.exit("fractalnow is not installed (apt-get install fractalnow)")
    if not os.path.exists(UGNIS):
        sys.exit("build ugnis first: cargo build --release")
    w, h = (int(v) for v in a.size.lower().split("x"))
    span_y = 3.0 * h / w
    tmp = tempfile.mkdtemp(prefix="ugnis-fn-")
    frac = os.path.join(tmp, "m.frac")
    rend = os.path.join(tmp, "r.rend")
    with open(frac, "w") as f:
        f.write(f"F075\nMANDELBROT\n-0.7 0 3 {span_y}\n2 {a.max_iter}\n")
    with open(rend, "w") as f:
        # Discrete iteration count, black inside, a three-colour gradient.
        f.write("R075\n1\n0x0\nITERATIONCOUNT\nDISCRETE\nIDENTITY\n0.01 0\n0 0x0 0.5 0xFF8800 1 0xFFFFFF\n")
    fn_exact = ["fractalnow", "-f", frac, "-r", rend, "-x", str(w), "-y", str(h), "-i", "1",
                "-j", str(a.threads), "-o", os.path.join(tmp, "fn_exact.ppm")]
    fn_default = ["fractalnow", "-f", frac, "-r", rend, "-x", str(w), "-y", str(h),
                  "-j", str(a.threads), "-o", os.path.join(tmp, "fn_default.ppm")]
    ug = [UGNIS, "escape", "mandelbrot", "--center=-0.7,0", "--width", "3", "--size", a.size,
          "--max-iter", str(a.max_iter), "--coloring", "bands", "--threads", str(a.threads),
          "-o", os.path.join(tmp, "ugnis.png")]
    times = {"fractalnow -i 1": [], "fractalnow default": [], "ugnis exact": []}
    for _ in range(a.runs):
        times["fractalnow -i 1"].append(timed(fn_exact))
        times["fractalnow default"].append(timed(fn_default))
        times["ugnis exact"].append(timed(ug))
    med = {k: statistics.median(v) for k, v in times.items()}
    print(f"Mandelbrot -0.7+0i width 3, {a.size}, max-iter {a.max_iter}, {a.threads} threads, "
          f"median of {a.runs} runs")
    for k, v in med.items():
        print(f"  {k:<20} {v:7.3f} s")
    r1 = med["ugnis exact"] / med["fractalnow -i 1"]
    r2 = med["ugnis exact"] / med["fractalnow default"]
    print(f"ratio ugnis / fractalnow -i 1:     {r1:.3f}  (target <= 0.2)")
    print(f"ratio ugnis / fractalnow default:  {r2:.3f}  (target < 1)")
    try:
        from PIL import Image
        import numpy as np
        fa = np.asarray(Image.open(os.path.join(tmp, "fn_exact.ppm")).convert("RGB"), dtype=int)
        ua = np.asarray(Image.open(os.path.join(tmp, "ugnis.png")).convert("RGB"), dtype=int)
        inside_f = fa.sum(axis=2) == 0
        inside_u = ua.sum(axis=2) == 0
        agree = (inside_f == inside_u).mean()
        print(f"inside/outside agreement with fractalnow: {agree * 100:.3f} % of pixels")
    except ImportError:
        pass
    shutil.rmtree(tmp, ignore_errors=True)
    sys.exit(0 if r1 <= 0.2 and r2 < 1 else 1)


if __name__ == "__main__":
    main()
