#!/usr/bin/env python3
"""Side-by-side comparison of ugnis and JWildfire's own renderer on flames JWildfire wrote.

For every JWildfire flame among the given files and folders (a `<flame>` whose `version` names
JWildfire, or a `<jwf-flame>` root), renders it with JWildfire (../shared/tools/jwildfire/
jwf-render.sh: JWildfire 9.00's FlameRenderer, fixed seed, the flame's own filter) and with
`ugnis render`, at the same size and quality (oversampling 1 in both, as JWildfire's command-line
renderer draws), pixels per unit scaling with the width, and prints
the PSNR (RGB, 8 bit, after a 3x3 box blur, as benches/compare_flam3.py) per flame, the median,
the share below 25 dB, the flames either program refused, and — apart — the flames for which
ugnis warned of a variation it cannot render (their figures are listed but kept out of the
main median). With --noise it also renders JWildfire with a second seed: JWildfire's own noise,
the bar to meet.

JWildfire's pictures are cached (--cache, keyed by the file's contents, index, size, quality
and seed): a second run renders only ugnis.

Needs: JWildfire built with ../shared/tools/jwildfire/build.sh (JWF_HOME, default
/tmp/jwildfire), python3 with numpy and pillow, and a release build of ugnis
(cargo build --release; UGNIS_BIN names another binary, e.g. for an A/B of two builds).

Examples:
  benches/compare_jwildfire.py                       # both corpora of ../shared/testdata
  benches/compare_jwildfire.py --noise --keep /tmp/jwf some.flame
  benches/compare_jwildfire.py --only linear3D       # flames whose file name contains linear3D
"""
import argparse
import hashlib
import os
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image, PngImagePlugin

# ugnis's pictures carry their flame; one with an image given inline holds megabytes of text.
PngImagePlugin.MAX_TEXT_CHUNK = 256 << 20

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
UGNIS = os.environ.get("UGNIS_BIN", os.path.join(TARGET, "release", "ugnis"))
SHARED = os.path.normpath(os.path.join(ROOT, "..", "shared"))
KIT = os.path.join(SHARED, "tools", "jwildfire")
DEFAULT_INPUTS = [os.path.join(SHARED, "testdata", "real-flames"),
                  os.path.join(SHARED, "testdata", "real-flames-2")]
FLAME_EXT = (".flame", ".flam3", ".fla", ".xml")


def flame_files(inputs):
    out = []
    for p in inputs:
        if os.path.isdir(p):
            for n in sorted(os.listdir(p)):
                if n.lower().endswith(FLAME_EXT):
                    out.append(os.path.join(p, n))
        else:
            out.append(p)
    return out


def jwildfire_flames(path):
    """Indices of the flames JWildfire wrote in a file, as both readers count them: each
    `<jwf-flame>`, and each `<flame>` outside one."""
    data = open(path, "rb").read()
    out = []
    index = 0
    depth_jwf = 0
    for m in re.finditer(rb"<(/?)(jwf-flame|flame)([\s>/])", data):
        closing, tag = m.group(1), m.group(2)
        if tag == b"jwf-flame":
            if closing:
                depth_jwf = max(0, depth_jwf - 1)
            else:
                out.append(index)
                index += 1
                depth_jwf += 1
        elif not closing and depth_jwf == 0:
            head = data[m.start():data.find(b">", m.start())]
            v = re.search(rb'\sversion="([^"]*)"', head)
            if v and v.group(1).strip().lower().startswith(b"jwildfire"):
                out.append(index)
            index += 1
    return out


def jwildfire(path, index, out, w, h, quality, seed):
    r = subprocess.run(["bash", os.path.join(KIT, "jwf-render.sh"), path, out, str(w), str(h),
                        str(quality), str(index), str(seed), "width"],
                       capture_output=True, text=True)
    end = [l for l in r.stdout.splitlines() if l.startswith("END ")]
    ok = r.returncode == 0 and end and end[-1].startswith("END ok") and os.path.exists(out)
    note = end[-1].split("\t")[-1] if end else (r.stderr.strip().splitlines() or ["?"])[-1]
    return ok, note


def cached_jwildfire(cache, path, index, w, h, quality, seed):
    key = hashlib.sha1(open(path, "rb").read()).hexdigest()[:16]
    out = os.path.join(cache, f"{key}-{index}-{w}x{h}-q{quality:g}-s{seed}.png")
    fail = out + ".fail"
    if os.path.exists(out):
        return out, None
    if os.path.exists(fail):
        return None, open(fail).read()
    ok, note = jwildfire(path, index, out, w, h, quality, seed)
    if ok:
        return out, None
    with open(fail, "w") as f:
        f.write(note)
    return None, note


def ugnis(path, index, out, w, h, quality, threads, supersample=None):
    cmd = [UGNIS, "render", path, "--index", str(index), "-o", out, "--size", f"{w}x{h}",
           "--quality", str(quality), "--threads", str(threads)]
    if supersample is not None:
        cmd += ["--supersample", str(supersample)]
    return subprocess.run(cmd, capture_output=True, text=True)


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


def missing_variations(stderr):
    return sorted(set(re.findall(r"variation '([^']+)' \(weight [^)]*\) not supported", stderr)))


def summary(label, values, bar):
    if not values:
        print(f"{label}: none")
        return
    below = sum(1 for v in values if v < bar)
    print(f"{label}: {len(values)} flames, median {statistics.median(values):.2f} dB, "
          f"mean {statistics.mean(values):.2f} dB, below {bar:g} dB: {below} "
          f"({100.0 * below / len(values):.1f} %)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="*", help="flame files or folders (default: both test corpora)")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--quality", type=float, default=200)
    ap.add_argument("--seed", type=int, default=1, help="JWildfire's seed")
    ap.add_argument("--noise", action="store_true", help="also render JWildfire with seed+1")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default=None, help="only files whose name contains this")
    ap.add_argument("--bar", type=float, default=25.0, help="the 'below' line, dB")
    ap.add_argument("--cache", default=os.path.join(tempfile.gettempdir(), "ugnis-jwf-cache"))
    ap.add_argument("--keep", default=None, help="directory to keep each flame's pictures in")
    a = ap.parse_args()
    if not os.path.exists(UGNIS):
        sys.exit(f"{UGNIS} missing: cargo build --release")
    jwf_home = os.environ.get("JWF_HOME", "/tmp/jwildfire")
    if not os.path.exists(os.path.join(jwf_home, "classpath.txt")):
        sys.exit(f"JWildfire is not built in {jwf_home}: run {KIT}/build.sh")
    w, h = (int(v) for v in a.size.split("x"))
    os.makedirs(a.cache, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="ugnis-jwf-")
    jobs = []
    for f in flame_files(a.inputs or DEFAULT_INPUTS):
        if a.only and a.only not in os.path.basename(f):
            continue
        for i in jwildfire_flames(f):
            jobs.append((f, i))
    print(f"{len(jobs)} JWildfire flames, {w}x{h}, quality {a.quality:g}")
    print(f"{'flame':<64} {'ugnis':>7}" + (f" {'noise':>7}" if a.noise else "") + "  notes")
    clean, warned, noise, refused = [], [], [], []
    for f, i in jobs:
        name = f"{os.path.basename(f)[-58:]}#{i}"
        ref, note = cached_jwildfire(a.cache, f, i, w, h, a.quality, a.seed)
        if ref is None:
            refused.append((name, f"JWildfire: {note[:70]}"))
            print(f"{name:<64} refused by JWildfire: {note[:70]}", flush=True)
            continue
        ug = os.path.join(tmp, "ug.png")
        # JWildfire's command-line renderer (CliUtils.renderFlame, which jwf-render.sh follows)
        # draws at spatial oversampling 1 whatever the file says; ugnis keeps the file's
        # `oversample` (as JWildfire's editor renders it), so it is told the same here.
        r = ugnis(f, i, ug, w, h, a.quality, a.threads, supersample=1)
        if r.returncode != 0:
            msg = (r.stderr.strip().splitlines() or ["?"])[-1][:70]
            refused.append((name, f"ugnis: {msg}"))
            print(f"{name:<64} refused by ugnis: {msg}", flush=True)
            continue
        R = load(ref)
        p = psnr(load(ug), R)
        miss = missing_variations(r.stderr)
        line = f"{name:<64} {p:7.2f}"
        if a.noise:
            ref2, _ = cached_jwildfire(a.cache, f, i, w, h, a.quality, a.seed + 1)
            pn = psnr(load(ref2), R) if ref2 else float("nan")
            noise.append(pn)
            line += f" {pn:7.2f}"
        if miss:
            warned.append(p)
            line += "  missing: " + ",".join(miss)
        else:
            clean.append(p)
        print(line, flush=True)
        if a.keep:
            os.makedirs(a.keep, exist_ok=True)
            stem = re.sub(r"[^A-Za-z0-9_.-]", "_", f"{os.path.basename(f)}-{i}")
            os.replace(ug, os.path.join(a.keep, f"{stem}.ug.png"))
            Image.open(ref).save(os.path.join(a.keep, f"{stem}.jwf.png"))
    print()
    summary("without missing variations", clean, a.bar)
    summary("with missing variations   ", warned, a.bar)
    summary("all rendered              ", clean + warned, a.bar)
    if a.noise:
        summary("JWildfire seed to seed     ", [v for v in noise if v == v], a.bar)
    print(f"refused: {len(refused)}")
    for n, why in refused:
        print(f"  {n}: {why}")


if __name__ == "__main__":
    main()
