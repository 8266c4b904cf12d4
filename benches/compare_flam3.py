#!/usr/bin/env python3
"""Side-by-side comparison of ugnis and flam3-render on random flames.

Generates random genomes with flam3-genome (seeded, so runs are repeatable), renders each with
flam3-render and with ugnis at the same size, quality and thread count, one after the other,
and prints per-flame wall times, the ugnis/flam3 wall-time ratio and ugnis's iterations per
second per thread. With --fidelity it renders flam3 at a higher quality as the reference and
prints the PSNR (RGB, after a 3x3 box blur) of ugnis and of flam3 at the same quality.

Needs: flam3-utils (flam3-render, flam3-genome), python3 with numpy and pillow, and a release
build of ugnis (cargo build --release).

Examples:
  benches/compare_flam3.py --count 10                    # speed, 640x480 q200, 2 threads, best of 3
  benches/compare_flam3.py --fidelity --count 20         # PSNR, q200 against flam3 q1000
  benches/compare_flam3.py --fidelity --vars 0-33        # classic variations 0..33
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
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UGNIS = os.path.join(ROOT, "target", "release", "ugnis")


def parse_vars(s):
    out = []
    for part in s.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return ",".join(str(v) for v in out)


def genome(seed, use_vars, width, height, quality, path):
    env = dict(os.environ, seed=str(seed), use_vars=use_vars)
    xml = subprocess.run(["flam3-genome"], env=env, capture_output=True, text=True, check=True).stdout
    m = re.search(r'size="(\d+) (\d+)"', xml)
    w0 = int(m.group(1))
    m2 = re.search(r'scale="([0-9.eE+-]+)"', xml)
    scale = float(m2.group(1)) * width / w0
    xml = xml.replace(m.group(0), f'size="{width} {height}"', 1)
    xml = xml.replace(m2.group(0), f'scale="{scale}"', 1)
    xml = re.sub(r'quality="[0-9.eE+-]+"', f'quality="{quality}"', xml, count=1)
    with open(path, "w") as f:
        f.write(xml)


def flam3(path, out, threads, qs=1.0, isaac_seed="ugnis"):
    # flam3's iteration randomness comes from isaac_seed (default: the current time, so two
    # renders started within one second would share their samples): always set it.
    env = dict(os.environ, **{"in": path, "out": out, "nthreads": str(threads), "qs": str(qs), "seed": "1",
                              "isaac_seed": isaac_seed})
    t = time.perf_counter()
    subprocess.run(["flam3-render"], env=env, capture_output=True, check=True)
    return time.perf_counter() - t


def ugnis(path, out, threads, quality=None):
    cmd = [UGNIS, "render", path, "-o", out, "--threads", str(threads)]
    if quality:
        cmd += ["--quality", str(quality)]
    t = time.perf_counter()
    subprocess.run(cmd, capture_output=True, check=True)
    return time.perf_counter() - t


def load(p):
    a = np.asarray(Image.open(p).convert("RGB")).astype(np.float64)
    # 3x3 box blur
    pad = np.pad(a, ((1, 1), (1, 1), (0, 0)), mode="edge")
    s = sum(pad[dy:dy + a.shape[0], dx:dx + a.shape[1]] for dy in range(3) for dx in range(3))
    return s / 9.0


def psnr(a, b):
    mse = ((a - b) ** 2).mean()
    return 99.0 if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--count", type=int, default=10)
    ap.add_argument("--seed", type=int, default=1000)
    ap.add_argument("--vars", default="0,1,2,3,4,5,14", help="flam3 variation numbers, e.g. 0-33")
    ap.add_argument("--size", default=None, help="WxH (default 640x480 for speed, 320x240 for fidelity)")
    ap.add_argument("--quality", type=float, default=200)
    ap.add_argument("--ref-quality", type=float, default=1000)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3,
                    help="speed: render each flame this many times with each program, alternating, "
                         "and keep the fastest (shared machines are noisy)")
    ap.add_argument("--fidelity", action="store_true")
    ap.add_argument("--keep", default=None, help="directory to keep the images in")
    a = ap.parse_args()
    if not os.path.exists(UGNIS):
        sys.exit("build ugnis first: cargo build --release")
    use_vars = parse_vars(a.vars)
    size = a.size or ("320x240" if a.fidelity else "640x480")
    w, h = (int(v) for v in size.split("x"))
    tmp = a.keep or tempfile.mkdtemp(prefix="ugnis-cmp-")
    os.makedirs(tmp, exist_ok=True)
    rows = []
    for i in range(a.count):
        seed = a.seed + i
        g = os.path.join(tmp, f"g{seed}.flam3")
        genome(seed, use_vars, w, h, a.quality, g)
        if a.fidelity:
            ref = os.path.join(tmp, f"ref{seed}.png")
            f3 = os.path.join(tmp, f"f3_{seed}.png")
            ug = os.path.join(tmp, f"ug{seed}.png")
            flam3(g, ref, a.threads, qs=a.ref_quality / a.quality, isaac_seed=f"ref{seed}")
            flam3(g, f3, a.threads, isaac_seed=f"q{seed}")
            ugnis(g, ug, a.threads)
            r = load(ref)
            p_ug, p_f3 = psnr(load(ug), r), psnr(load(f3), r)
            rows.append((seed, p_ug, p_f3))
            print(f"seed {seed}: ugnis q{a.quality:g} {p_ug:6.2f} dB   flam3 q{a.quality:g} {p_f3:6.2f} dB", flush=True)
        else:
            f3 = os.path.join(tmp, f"f3_{seed}.png")
            ug = os.path.join(tmp, f"ug{seed}.png")
            t_f3, t_ug = float("inf"), float("inf")
            for _ in range(max(1, a.repeat)):
                t_f3 = min(t_f3, flam3(g, f3, a.threads))
                t_ug = min(t_ug, ugnis(g, ug, a.threads))
            samples = a.quality * w * h
            ips = samples / t_ug / a.threads
            rows.append((seed, t_f3, t_ug, ips))
            print(f"seed {seed}: flam3 {t_f3:6.2f} s   ugnis {t_ug:6.2f} s   ratio {t_ug / t_f3:5.2f}   "
                  f"ugnis {ips / 1e6:5.2f} M iter/s/thread", flush=True)
    if a.fidelity:
        ug = [r[1] for r in rows]
        f3 = [r[2] for r in rows]
        print(f"\nPSNR against flam3 q{a.ref_quality:g} ({len(rows)} flames, vars {a.vars}, {size}):")
        print(f"  ugnis q{a.quality:g}: median {statistics.median(ug):.2f} dB, min {min(ug):.2f} dB")
        print(f"  flam3 q{a.quality:g}: median {statistics.median(f3):.2f} dB, min {min(f3):.2f} dB")
    else:
        tf = sum(r[1] for r in rows)
        tu = sum(r[2] for r in rows)
        ratios = [r[2] / r[1] for r in rows]
        print(f"\n{len(rows)} flames, {size}, quality {a.quality:g}, {a.threads} threads, vars {a.vars}, "
              f"best of {max(1, a.repeat)}:")
        print(f"  total wall time: flam3 {tf:.2f} s, ugnis {tu:.2f} s, ratio {tu / tf:.3f}")
        print(f"  per-flame ratio: median {statistics.median(ratios):.3f}, worst {max(ratios):.3f}")
        print(f"  ugnis: median {statistics.median(r[3] for r in rows) / 1e6:.2f} M iterations/s/thread")
    if not a.keep:
        print(f"  (images in {tmp})")


if __name__ == "__main__":
    main()
