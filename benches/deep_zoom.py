#!/usr/bin/env python3
"""Deep-zoom speed of `ugnis escape` against Fractalshades (its perturbation Mandelbrot and
Burning Ship with bilinear approximation), same view, size and iterations, on the same threads.
Neither side detects the interior early (Fractalshades' `interior_detect` is off, its default;
ugnis has none in deep zoom): interior pixels run to the iteration limit on both.

Fractalshades' Burning Ship iterates y ← 2|xy| − b, the mirror image of ugnis'
(|Re z| + i|Im z|)² + c: its view is given the negated imaginary part.

Fractalshades runs each view twice in one process and its second run is timed, so that
numba's compilation does not count. It needs `pip install fractalshades gmpy2 "numpy<2.4"`
(Fractalshades 1.2.1's reference loop fails on numpy 2.4; and Debian's libgmp-dev
libmpfr-dev libmpc-dev); give its Python with --fs-python (skipped when absent).

Fractalshades' default bilinear tolerance (1e-6) is less exact than ugnis' default (2^-44):
`--accuracy` measures both programs' continuous counts against exact iteration in MPFR on a
16x12 grid of each view (ugnis' from its EXR iteration data, Fractalshades' from its raw
arrays), and each Mandelbrot view is also timed with Fractalshades at --fs-matched, the
tolerance at which its accuracy matches ugnis'. ugnis' own figure (continuous counts against
an exact per-pixel computation in big fixed point) is the test `escape::deep::tests`
(`cargo test --lib escape::deep`); on the seahorse view's own 16x12 grid (width 1e-25, 30,000
iterations) `the_bench_view_is_as_exact_as_fractalshades_at_matched_tolerance` (run with
`--ignored`; UGNIS_BLA_EPS=a,b also reports other tolerances) gets 190 of 192 pixels (99.0 %)
at the default 2^-44, and also at 2^-43, 2^-42 and 1e-12; 188 at 1e-10, 178 at 1e-6 (with
the quadratic steps; with the bilinear ones it was 189 at 1e-12 and 185 at 1e-10).

    python3 benches/deep_zoom.py --ugnis target/release/ugnis --fs-python /path/to/python

Seahorse with quadratic steps in ugnis' plain-f64 loop (src/escape/bla_quad.rs), 2 threads,
640x480, load 8-10: ugnis 7.18 s wall, 2.63 s CPU; Fractalshades 9.06 s (4.23 s CPU) at its
default, 34.71 s (18.35 s CPU) at 1e-14: wall ratio 0.79 and 0.21, CPU ratio 0.62 and 0.14.
On one thread, back to back, the bilinear build took 10.2-11.1 s CPU and the quadratic one
2.5-2.6 s; --accuracy unchanged at 99.0 % (190 of 192); at --bla-tolerance 1e-6 ugnis takes
0.95 s CPU on one thread (86 % of the grid within 0.05, as before). The older figures below
are for the bilinear steps.

Measured on 2 threads, 640x480, with the 2-core machine at load 11-12 (ugnis' wall time over
Fractalshades', CPU ratio in brackets): seahorse 1e-25 2.78 (2.70) against Fractalshades'
default tolerance, 0.83 (0.79) against its matched 1e-14; misiurewicz 1e-100 0.12 (0.09),
matched 0.11 (0.09); misiurewicz 1e-1000 0.07 (0.09), matched 0.06 (0.08); burning ship 1e-100
0.23 (0.23). Fractalshades' own accuracy (--accuracy, 16x12): seahorse 85.4 % at 1e-6 and
99.0 % at 1e-14; misiurewicz 1e-100 and 1e-1000 100 % at both; burning ship 1e-100 43.8 % and
46.4 %.

The Burning Ship's bilinear steps (real 2x2 matrices, src/escape/bla_ship.rs) on the deep ship
views (20,000 iterations at most, 640x480, 2 threads, load 8-9; ugnis' wall time over
Fractalshades', CPU ratio in brackets): at 1e-100 3.05 (3.19) with every iteration perturbed
singly, 0.51 (0.53) with the steps (ugnis 8.96 -> 1.35 CPU s); at 1e-30 0.63 (0.69) -> 0.54
(0.57). Accuracy (--accuracy, 16x12): ugnis 100 % at both depths, Fractalshades at its
default 1e-6 46.4 % (1e-30) and 38.5 % (1e-100).

The dense view near 1e-300 (200,000 iterations at most, pixels escape after about 91,000;
load 10-12): ugnis 20.57 s wall, 5.15 s CPU; Fractalshades 44.57 s (13.61 s CPU) at its
default, 169.39 s (39.14 s CPU) at 1e-14: wall ratio 0.46 and 0.12, CPU ratio 0.38 and 0.13.
Accuracy (16x12): ugnis, Fractalshades at 1e-6 and at 1e-14 all 100 %: this view does not
show the misses a near-parabolic view such as the seahorse does. On the seahorse view the
same --accuracy gives ugnis 99.0 % (190 of 192, as the Rust test).

Seahorse after the first-level radius by index and the AVX-512 build of the plain loop (load
10-12): ugnis 25.25 s wall, 10.29 s CPU; Fractalshades 10.22 s (3.87 s CPU) at its default,
39.32 s (15.68 s CPU) at 1e-14: wall ratio 2.47 and 0.64, CPU ratio 2.66 and 0.66.

Seahorse before that, with the machine at load 9-10 (other jobs): ugnis 20.29 s wall, 11.18 s CPU;
Fractalshades 6.17 s (3.70 s CPU) at its default, 19.75 s (14.99 s CPU) at 1e-14: CPU ratio
3.02 and 0.75. ugnis' CPU time at other tolerances (same load): 2^-43 11.11 s, 1e-12 9.78 s.
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

# The centre of Fractalshades' example "12 - Burning ship deep"
# (examples/batch_mode/12-burning_ship_deep.py: a period-9,622 miniship of size 3.4e-265), in
# ugnis' orientation (imaginary part negated): at width 1e-100 pixels escape after 4,700-5,300
# iterations, where the ship's bilinear steps matter.
SHIPD_X = ("-1.99638112292592965329403782831125346996664185255135402827974584999638456165654"
           "33002317348463723892008844734003260474022592153652996510000493079672207971742209203082500"
           "39037884064184875313550754352410343246674089430454249309097057276774162871180276065193880"
           "170743903875782")
SHIPD_Y = ("-0.00000476330372839277074601469236202986586671169161209597457133172150779470960"
           "76040509814670657369206760374813788282766429440720697568351829534511099050778810611398876"
           "61561617020726899218853890425452233104923366681895875677542245236396274857406762304353824"
           "848557938906613374564")

# A dense, chaotic view near 1e-300 on the way to the minibrot of Fractalshades' example
# "23 - A deep mini" (examples/batch_mode/23-deep_min.py, width 5.07e-433; the same path as its
# "Dinkidau flake" at 1.7e-157): a period-57,853 minibrot lies in the view, and its pixels
# escape after about 91,000 iterations.
DENSE_X = ("-1.99996619445037030418434688506350579675531241540724851511761922944801584242342684381"
          "37612977886891381228704640656094986435381057574477216648567249609280392009708065964646"
          "97897247034380275662515774719795646696735873798312804539648952681115225456179242935106"
          "83774588487880585490216939383687209739405059004605769908796701019623976540655194251135"
          "32489358706769123819542065835894736637726501046377854193929498727550588955307380897400"
          "79985776336454731048155381424443368009147832298545439060874543314328347318610344753331"
          "544040936498231198149727109")
DENSE_Y = ("0.000000000000000000000000000000000300138243679093832407249730397759249873468311907733"
          "35270174257280120474975614823581185647299288414075519224186504978181625475848084062264"
          "19681319987510966551024915920858367060072851094384239104512934585936736294083320495556"
          "91125564103474186024773553414471657579951070239079740422320855859219398895622812831264"
          "74253580211041231506233164036106101811335050020786087353656381162350128598636029702826"
          "87765675758728641685358330772131661136113532338021950485899263595349420350880557330865"
          "130440135716258565997502285180701052571648187007997490077027")

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
    ("burning ship deep 1e-30", SHIPD_X, SHIPD_Y, "1e-30", 20000, "burning-ship"),
    ("burning ship deep 1e-100", SHIPD_X, SHIPD_Y, "1e-100", 20000, "burning-ship"),
    ("dense 1e-300", DENSE_X, DENSE_Y, "1e-300", 200000, "mandelbrot"),
]

# Fractalshades' bilinear tolerance at which its continuous counts are as exact as ugnis'
# default (2^-44): on the seahorse view (16x12 grid, --accuracy) its default 1e-6 leaves
# 85 % of pixels within 0.05 of exact iteration, 1e-10 96 %, 1e-12 98 %, 1e-14 and no
# bilinear steps at all 99 %.
FS_MATCHED = "1e-14"

FS_SCRIPT = r"""
import math, os, sys, time, tempfile
os.environ.setdefault("NUMBA_NUM_THREADS", sys.argv[6])
import mpmath
import fractalshades as fs
import fractalshades.models as fsm

x, y, dx, max_iter, size = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
ship = sys.argv[7] == "burning-ship"
eps = None if sys.argv[8] == "none" else float(sys.argv[8])
accuracy = sys.argv[9] == "accuracy"
if ship:
    y = y[1:] if y.startswith("-") else "-" + y
nx, ny = (int(v) for v in size.split("x"))
digits = max(20, int(-mpmath.log10(mpmath.mpf(dx))) + 10)


def render():
    d = tempfile.mkdtemp()
    if ship:
        f = fsm.Perturbation_burning_ship(d, flavor="Burning ship")
        f.zoom(precision=digits, x=x, y=y, dx=dx, nx=nx, xy_ratio=nx / ny, theta_deg=0.0)
        f.calc_std_div(calc_name="bench", subset=None, max_iter=max_iter, M_divergence=256.0,
                       calc_hessian=False, BLA_eps=eps)
    else:
        f = fsm.Perturbation_mandelbrot(d)
        f.zoom(precision=digits, x=x, y=y, dx=dx, nx=nx, xy_ratio=nx / ny, theta_deg=0.0)
        f.calc_std_div(calc_name="bench", subset=None, max_iter=max_iter, M_divergence=256.0,
                       epsilon_stationnary=1e-3, calc_dzndc=False, BLA_eps=eps)
    t, p = time.time(), time.process_time()
    f.calc_raw("bench")
    return f, (time.time() - t, time.process_time() - p)


if not accuracy:
    render()
    f, (wall, cpu) = render()
    print(wall, cpu)
    sys.exit(0)

# Accuracy: every pixel's continuous count n + 1 - log2(ln|z|) from Fractalshades' raw
# arrays (escape iteration, final z) against the same count from the pixel iterated directly
# in MPFR (gmpy2) at twice the digits of the view plus 200 bits.
import gmpy2
f, _ = render()
M2 = 256.0 ** 2
prec = int(-mpmath.log(mpmath.mpf(dx), 2) * 2 + 200)
gmpy2.get_context().precision = prec
X, Y, DX = gmpy2.mpfr(x), gmpy2.mpfr(y), gmpy2.mpfr(dx)


def nu(n, z):
    return n + 1 - math.log(math.log(abs(z))) / math.log(2)


def exact(p):
    cx = X + gmpy2.mpfr(p.real) * DX
    cy = Y + gmpy2.mpfr(p.imag) * DX
    zx = zy = gmpy2.mpfr(0)
    for n in range(1, max_iter + 1):
        if ship:
            # Fractalshades' Burning Ship: y <- 2|xy| - b.
            zx, zy = zx * zx - zy * zy + cx, 2 * abs(zx * zy) - cy
        else:
            zx, zy = zx * zx - zy * zy + cx, 2 * zx * zy + cy
        a, b = float(zx), float(zy)
        if not a * a + b * b <= M2:
            return n, complex(a, b)
    return None


good = total = 0
for cs in f.chunk_slices():
    _, c_pix, Z, U, stop_reason, stop_iter = f.reload_data(cs, "bench")
    for k in range(len(c_pix)):
        e = exact(complex(c_pix[k]))
        if e is None:
            ok = stop_reason[0, k] == 0
        else:
            ok = stop_reason[0, k] == 1 and abs(nu(int(stop_iter[0, k]), Z[0, k]) - nu(*e)) < 0.05
        good += bool(ok)
        total += 1
print(good / total)
"""


# ugnis' accuracy: its iteration data (EXR channels N and NF, read here without an EXR library:
# ZIP or uncompressed scanlines) on a 16x12 grid against the same exact iteration in MPFR, at
# ugnis' pixel centres (pixel (i, j) at ((i + 1/2)/w - 1/2, 1/2 - (j + 1/2)/h) times the view's
# width and height).
UG_ACC_SCRIPT = r"""
import math, struct, sys, zlib
import gmpy2
import mpmath

exr, x, y, dx, max_iter, ship = sys.argv[1:7]
max_iter, ship = int(max_iter), ship == "burning-ship"


def read_counts(path):
    b = open(path, "rb").read()
    p, attrs = 8, {}
    while b[p] != 0:
        e = b.index(b"\0", p); name = b[p:e].decode(); p = e + 1
        e = b.index(b"\0", p); p = e + 1
        size = struct.unpack_from("<i", b, p)[0]; p += 4
        attrs[name] = b[p:p + size]; p += size
    p += 1
    chl, chans, q = attrs["channels"], [], 0
    while chl[q] != 0:
        e = chl.index(b"\0", q); chans.append(chl[q:e].decode()); q = e + 17
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    comp = attrs["compression"][0]
    per = {0: 1, 2: 1, 3: 16}[comp]
    offs = struct.unpack_from("<%dQ" % ((h + per - 1) // per), b, p)
    ch = {c: [[0] * w for _ in range(h)] for c in chans}
    for off in offs:
        y, size = struct.unpack_from("<ii", b, off)
        data = b[off + 8:off + 8 + size]
        lines = min(per, y1 - y + 1)
        if comp != 0 and size < lines * w * 4 * len(chans):
            t = bytearray(zlib.decompress(data))
            for i in range(1, len(t)):
                t[i] = (t[i - 1] + t[i] - 128) & 0xFF
            half = (len(t) + 1) // 2
            r = bytearray(len(t))
            r[0::2], r[1::2] = t[:half], t[half:]
            data = bytes(r)
        q = 0
        for l in range(lines):
            for c in chans:
                ch[c][y - y0 + l] = struct.unpack_from("<%d%s" % (w, "I" if c == "N" else "f"),
                                                       data, q)
                q += 4 * w
    return w, h, [[None if ch["N"][j][i] == 0xFFFFFFFF else ch["N"][j][i] + ch["NF"][j][i]
                   for i in range(w)] for j in range(h)]


w, h, got = read_counts(exr)
gmpy2.get_context().precision = int(-mpmath.log(mpmath.mpf(dx), 2) * 2 + 200)
X, Y, DX = gmpy2.mpfr(x), gmpy2.mpfr(y), gmpy2.mpfr(dx)
M2 = 256.0 ** 2


def exact(cx, cy):
    zx = zy = gmpy2.mpfr(0)
    for n in range(1, max_iter + 1):
        if ship:
            zx, zy = zx * zx - zy * zy + cx, 2 * abs(zx * zy) + cy
        else:
            zx, zy = zx * zx - zy * zy + cx, 2 * zx * zy + cy
        a, b = float(zx), float(zy)
        if not a * a + b * b <= M2:
            return n + 1 - math.log(math.log(math.hypot(a, b))) / math.log(2)
    return None


good = 0
for j in range(h):
    for i in range(w):
        cx = X + gmpy2.mpfr((i + 0.5) / w - 0.5) * DX
        cy = Y + gmpy2.mpfr(0.5 - (j + 0.5) / h) * DX * h / w
        e, g = exact(cx, cy), got[j][i]
        good += (e is None and g is None) or (e is not None and g is not None
                                              and abs(e - g) < 0.05)
print(good / (w * h))
"""


def ugnis_accuracy(exe, py, view, threads):
    name, x, y, width, max_iter, kind = view
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "grid.exr")
        r = subprocess.run([exe, "escape", kind, "--center", f"{x},{y}", "--width", width,
                            "--size", "16x12", "--max-iter", str(max_iter), "--bailout", "256",
                            "--threads", str(threads), "-o", out], capture_output=True, text=True)
        if r.returncode != 0:
            return None, r.stderr.strip()
        r = subprocess.run([py, "-c", UG_ACC_SCRIPT, out, x, y, width, str(max_iter), kind],
                           capture_output=True, text=True)
        if r.returncode != 0:
            return None, r.stderr.strip().splitlines()[-1:]
        return float(r.stdout.strip().splitlines()[-1]), ""


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


def run_fractalshades(py, view, size, threads, eps="1e-6", accuracy=False):
    name, x, y, width, max_iter, kind = view
    # Fractalshades' dx is the view's width.
    r = subprocess.run([py, "-c", FS_SCRIPT, x, y, width, str(max_iter), size, str(threads),
                        kind, eps, "accuracy" if accuracy else "time"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr.strip().splitlines()[-1:]
    return [float(v) for v in r.stdout.strip().splitlines()[-1].split()], ""


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
    ap.add_argument("--fs-matched", default=FS_MATCHED,
                    help="also time Fractalshades at this bilinear tolerance (its accuracy "
                         "then matches ugnis' default; 'off' to skip)")
    ap.add_argument("--accuracy", action="store_true",
                    help="instead of timing, the fraction of a 16x12 grid of Fractalshades' "
                         "pixels whose continuous count is within 0.05 of exact iteration, at "
                         "its default tolerance and at --fs-matched")
    a = ap.parse_args()
    views = [v for v in VIEWS if not a.only or a.only in v[0]]
    if a.accuracy:
        if not a.fs_python:
            sys.exit("--accuracy needs --fs-python")
        print(f"{'view':24} pixels within 0.05 of exact (16x12)")
        for v in views:
            r, err = ugnis_accuracy(a.ugnis, a.fs_python, v, a.threads)
            cols = ["ugnis: " + (f"{100 * r:.1f} %" if r is not None else f"failed {err}")]
            for eps in ["1e-6"] + ([a.fs_matched] if a.fs_matched != "off" else []):
                r, err = run_fractalshades(a.fs_python, v, "16x12", a.threads, eps, True)
                cols.append(f"Fractalshades eps {eps}: " + (f"{100 * r[0]:.1f} %" if r else f"failed {err}"))
            print(f"{v[0]:24} " + ", ".join(cols), flush=True)
        return
    # On a machine other jobs load, wall times stretch with the load; CPU times (all threads)
    # do much less, so both are shown.
    print(f"{'view':24} {'size':>8} {'iters':>6} {'ugnis s':>9} {'Fractalshades s':>16} "
          f"{'ratio':>6} {'CPU s':>7} {'FS CPU s':>9} {'ratio':>6}")

    def row(label, v, tu, tf):
        cols = [f"{tu[0]:.2f}", f"{tf[0]:.2f}" if tf else "-",
                f"{tu[0] / tf[0]:.2f}" if tf else "-", f"{tu[1]:.2f}",
                f"{tf[1]:.2f}" if tf else "-", f"{tu[1] / tf[1]:.2f}" if tf else "-"]
        print(f"{label:24} {a.size:>8} {v[4]:>6} {cols[0]:>9} {cols[1]:>16} {cols[2]:>6} "
              f"{cols[3]:>7} {cols[4]:>9} {cols[5]:>6}", flush=True)

    for v in views:
        tu, err = time_ugnis(a.ugnis, v, a.size, a.threads)
        tf = None
        if a.fs_python:
            tf, ferr = run_fractalshades(a.fs_python, v, a.size, a.threads)
            if tf is None:
                print(f"  Fractalshades failed: {ferr}", file=sys.stderr)
        if tu is None:
            print(f"{v[0]:24} {a.size:>8} {v[4]:>6} failed: {err}", flush=True)
            continue
        row(v[0], v, tu, tf)
        if a.fs_python and a.fs_matched != "off" and v[5] == "mandelbrot":
            tm, ferr = run_fractalshades(a.fs_python, v, a.size, a.threads, a.fs_matched)
            if tm is None:
                print(f"  Fractalshades at {a.fs_matched} failed: {ferr}", file=sys.stderr)
            else:
                row(f"  FS at tolerance {a.fs_matched}", v, tu, tm)
        if a.fs_tolerance:
            te, err = time_ugnis(a.ugnis, v, a.size, a.threads, 1e-6)
            if te is None:
                print(f"  ugnis --bla-tolerance 1e-6 failed: {err}", file=sys.stderr)
                continue
            row("  ugnis at tolerance 1e-6", v, te, tf)


if __name__ == "__main__":
    main()
