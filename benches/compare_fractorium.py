#!/usr/bin/env python3
"""Side-by-side comparison of ugnis and Fractorium's CPU renderer (emberrender).

For each flame: renders Fractorium at a high quality as the reference, Fractorium at the test
quality (how close Fractorium comes to itself) and ugnis at the test quality, at the same size,
and prints the PSNR (RGB, after a 3x3 box blur, as benches/compare_flam3.py) of each against the
reference. A flame whose variations either program does not know is skipped (emberrender drops
unknown variations silently). With --speed it also prints the wall times at the test quality
and the ugnis/Fractorium ratio (same samples per pixel, same size and thread count).

Flames come from flame files given on the command line (every <flame> of each, up to --per-file)
and, with --generated N, from N flames made here of Fractorium-only variations with their
default parameters (seeded: repeatable), marked as written by Fractorium.

Needs: Fractorium's renderer built with ../shared/tools/ember/build.sh (EMBER_HOME, default
/tmp/ember), python3 with numpy and pillow, and a release build of ugnis (cargo build --release).

UGNIS_BIN names another ugnis binary to compare (an A/B of two builds); --keep DIR keeps each
flame's three pictures (ref, fr, ug) to look at. --ugnis-rule fractorium makes ugnis index the
palette as Fractorium does for every file (by default ugnis follows the program that wrote the
file, as Fractorium does not), to tell rendering differences from that deliberate one.

Examples:
  benches/compare_fractorium.py ../shared/testdata/real-flames/*.flame
  benches/compare_fractorium.py --generated 20 --speed
"""
import argparse
import glob
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UGNIS = os.environ.get("UGNIS_BIN", os.path.join(ROOT, "target", "release", "ugnis"))
KIT = os.path.normpath(os.path.join(ROOT, "..", "shared", "tools", "ember"))
EMBER_HOME = os.environ.get("EMBER_HOME", "/tmp/ember")


def flames_in(path):
    data = open(path, "rb").read()
    return [m.start() for m in re.finditer(rb"<flame[\s>/]", data)]


def size_of(path, index):
    data = open(path, "rb").read()
    s = flames_in(path)[index]
    head = data[s:data.index(b">", s)]
    m = re.search(rb'size="(\d+) (\d+)"', head)
    return (int(m.group(1)), int(m.group(2))) if m else (100, 100)


def ember(path, index, out, width, height, quality, threads):
    env = dict(os.environ, EMBER_HOME=EMBER_HOME, EMBER_THREADS=str(threads),
               EMBER_HEIGHT=str(height), EMBER_STRICT="1", EMBER_SEED=str(random.random()))
    t = time.perf_counter()
    r = subprocess.run([os.path.join(KIT, "ember-render.sh"), path, out, str(width), str(quality),
                        str(index)], env=env, capture_output=True, text=True)
    return time.perf_counter() - t, r


def ugnis(path, index, out, width, height, quality, threads):
    cmd = [UGNIS, "render", path, "--index", str(index), "-o", out, "--size",
           f"{width}x{height}", "--quality", str(quality), "--threads", str(threads), "--strict"]
    t = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True)
    return time.perf_counter() - t, r


def load(p):
    a = np.asarray(Image.open(p).convert("RGB")).astype(np.float64)
    pad = np.pad(a, ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = a.shape[:2]
    return sum(pad[dy:dy + h, dx:dx + w] for dy in range(3) for dx in range(3)) / 9.0


def psnr(a, b):
    if a.shape != b.shape:
        return float("nan")
    mse = np.mean((a - b) ** 2)
    return 99.0 if mse == 0 else 10 * np.log10(255.0 ** 2 / mse)


def fractorium_only_variations():
    """Regular Fractorium variations that flam3 does not have (from Fractorium's own list)."""
    out = subprocess.run([UGNIS, "info", "--variations"], capture_output=True, text=True).stdout
    names = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 2 and parts[1] == "Fractorium" and "post_ only" not in line:
            names.append(parts[0])
    return names


def generated(n, seed, folder):
    rng = random.Random(seed)
    names = fractorium_only_variations()
    files = []
    for k in range(n):
        xforms = []
        for i in range(3):
            a = [rng.uniform(-1, 1) for _ in range(6)]
            v = rng.choice(names)
            xforms.append(f'<xform weight="{rng.uniform(0.2, 1):.4f}" color="{i / 2:.2f}" '
                          f'linear="{rng.uniform(0.2, 0.8):.3f}" {v}="{rng.uniform(0.2, 0.8):.3f}" '
                          f'coefs="{" ".join(f"{x:.5f}" for x in a)}"/>')
        pal = "".join(f"{int(127 + 127 * np.sin(j / 40)):02X}{j:02X}{255 - j:02X}" for j in range(256))
        # Marked as Fractorium marks what it writes, so that ugnis draws them by Fractorium's
        # rules (palette index, tone scale) as it does Fractorium's own files.
        text = (f'<flame version="EMBER-25.25.12.1" name="gen{k}" size="400 300" center="0 0" scale="80" quality="50" '
                f'gamma="4" brightness="4" vibrancy="1">\n' + "\n".join(xforms) +
                f'\n<palette count="256" format="RGB">{pal}</palette>\n</flame>\n')
        p = os.path.join(folder, f"gen{k:03d}.flame")
        open(p, "w").write(text)
        files.append(p)
    return files


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="*")
    ap.add_argument("--generated", type=int, default=0, help="flames of Fractorium-only variations")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--per-file", type=int, default=3, help="flames taken from each file")
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--quality", type=int, default=200)
    ap.add_argument("--ref-quality", type=int, default=1000)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--speed", action="store_true", help="also print wall times and their ratio")
    ap.add_argument("--keep", default=None, help="directory to keep each flame's three pictures in")
    ap.add_argument("--ugnis-rule", default=None,
                    help="palette rule ugnis uses for every file (flam3, apophysis, fractorium, jwildfire)")
    a = ap.parse_args()
    if not os.path.exists(UGNIS):
        sys.exit(f"{UGNIS} missing: cargo build --release")
    if not os.path.exists(os.path.join(EMBER_HOME, "bin", "emberrender")):
        sys.exit(f"emberrender missing in {EMBER_HOME}: run {KIT}/build.sh")
    tmp = tempfile.mkdtemp(prefix="ugnis-fractorium-")
    jobs = []
    for f in a.files:
        for i in range(min(a.per_file, len(flames_in(f)))):
            jobs.append((f, i))
    for f in generated(a.generated, a.seed, tmp):
        jobs.append((f, 0))
    print(f"{'flame':<48} {'fractorium':>10} {'ugnis':>8} {'diff':>6}" +
          (f" {'t_fr':>7} {'t_ugnis':>7} {'ratio':>6}" if a.speed else ""))
    rows = []
    for f, i in jobs:
        w0, h0 = size_of(f, i)
        h = max(1, round(a.width * h0 / w0))
        name = f"{os.path.basename(f)[:40]}#{i}"
        ref, fr, ug = (os.path.join(tmp, f"{x}.png") for x in ("ref", "fr", "ug"))
        src = f
        if a.ugnis_rule:
            src = os.path.join(tmp, "ruled" + os.path.splitext(f)[1])
            data = re.sub(rb'\sugnis_palette_index="[^"]*"', b"", open(f, "rb").read())
            rule = a.ugnis_rule.encode()
            data = re.sub(rb"<flame(\s|>)", b'<flame ugnis_palette_index="' + rule + b'"\\1', data)
            open(src, "wb").write(data)
        t_ug, r = ugnis(src, i, ug, a.width, h, a.quality, a.threads)
        if r.returncode != 0:
            print(f"{name:<48} skipped: ugnis: {r.stderr.strip().splitlines()[-1][:60]}")
            continue
        _, r = ember(f, i, ref, a.width, h, a.ref_quality, a.threads)
        if r.returncode != 0:
            print(f"{name:<48} skipped: Fractorium: {(r.stderr.strip().splitlines() or ['?'])[-1][:60]}")
            continue
        t_fr, _ = ember(f, i, fr, a.width, h, a.quality, a.threads)
        R = load(ref)
        p_fr, p_ug = psnr(load(fr), R), psnr(load(ug), R)
        rows.append((p_fr, p_ug, t_fr, t_ug))
        line = f"{name:<48} {p_fr:10.2f} {p_ug:8.2f} {p_ug - p_fr:6.2f}"
        if a.speed:
            line += f" {t_fr:7.2f} {t_ug:7.2f} {t_ug / t_fr:6.2f}"
        print(line, flush=True)
        if a.keep:
            os.makedirs(a.keep, exist_ok=True)
            stem = re.sub(r"[^A-Za-z0-9_.-]", "_", f"{os.path.basename(f)}-{i}")
            for x, p in (("ref", ref), ("fr", fr), ("ug", ug)):
                os.replace(p, os.path.join(a.keep, f"{stem}.{x}.png"))
    if rows:
        d = [r[1] - r[0] for r in rows]
        print(f"\n{len(rows)} flames: Fractorium q{a.quality} vs its q{a.ref_quality}: median "
              f"{statistics.median(r[0] for r in rows):.2f} dB; ugnis q{a.quality}: median "
              f"{statistics.median(r[1] for r in rows):.2f} dB; difference median {statistics.median(d):+.2f}, "
              f"worst {min(d):+.2f} dB")
        if a.speed:
            ratios = [r[3] / r[2] for r in rows]
            print(f"wall-time ratio ugnis/Fractorium: median {statistics.median(ratios):.2f}, "
                  f"total {sum(r[3] for r in rows) / sum(r[2] for r in rows):.2f}")


if __name__ == "__main__":
    main()
