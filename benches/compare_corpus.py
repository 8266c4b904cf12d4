#!/usr/bin/env python3
"""Side-by-side comparison of ugnis and each real flame's own program, for the flames that
benches/compare_jwildfire.py does not measure (those JWildfire 1.0 and later wrote).

Each <flame> of the given files and folders (default: both test corpora) is assigned to the
program that wrote it, from its attributes:

  version="FLAM3-…", no version (flam3, Electric Sheep genomes), "fr0st …"  -> flam3-render
  version="Apophysis …", "EMBER-…" (Fractorium), "FLAM3H…" (Houdini)        -> emberrender
  version="0.16 (06.11.2011)" (JWildfire's first releases, 2011)             -> JWildfire
  version="JWildfire …", <jwf-flame>                                         -> skipped

(Apophysis itself does not run here; Fractorium, which reads its files, stands in for it; ugnis
indexes an Apophysis palette by Apophysis' rule, Fractorium by its own, so --ugnis-rule
fractorium shows the rendering differences alone.) The
flame is cut out of its file and rewritten to --width px (height from its aspect, pixels per unit
scaled with the width) at --quality; the reference program renders it twice, with two seeds, and
ugnis once at the same size and quality. Printed per flame: PSNR (RGB, 8 bit, after a 3x3 box
blur, the helpers of benches/compare_jwildfire.py) of ugnis against the reference's first render
and of the reference's second render against its first (the reference's own noise, the bar to
meet); then per writer the medians and the count of flames below their noise - 3 dB.

Reference pictures are cached (--cache, keyed by the flame's text, size, quality and seed): a
second run renders only ugnis. --keep DIR keeps each flame's pictures (.ref, .ref2, .ug).

Needs: flam3-utils (flam3-render), Fractorium's emberrender (../shared/tools/ember/build.sh,
EMBER_HOME), for the 2011 JWildfire files JWildfire (../shared/tools/jwildfire/build.sh,
JWF_HOME), python3 with numpy and pillow, and a release build of ugnis (CARGO_TARGET_DIR or
UGNIS_BIN as in compare_jwildfire.py).

Examples:
  benches/compare_corpus.py                           # both corpora, 160 px, q200
  benches/compare_corpus.py --only render0 --keep /tmp/cmp
  benches/compare_corpus.py --writer apophysis --ugnis-rule fractorium
"""
import argparse
import hashlib
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

import compare_flam3 as f3
import compare_fractorium as fr
import compare_jwildfire as jw

# Which program draws a writer's files.
PROGRAM = {"flam3": "flam3", "electricsheep": "flam3", "fr0st": "flam3",
           "apophysis": "ember", "fractorium": "ember", "flam3h": "ember",
           "jwildfire-2011": "jwildfire"}


def attr(head, name):
    m = re.search(rb"\s" + name.encode() + rb'\s*=\s*"([^"]*)"', head)
    return m.group(1).decode("utf-8", "replace") if m else None


def flames(path):
    """(index, writer, text of the <flame> element) of every flame of a file, indexed as ugnis
    and Fractorium count them (every <flame>, in order)."""
    data = open(path, "rb").read()
    jwf_root = b"<jwf-flame" in data
    out = []
    for i, m in enumerate(re.finditer(rb"<flame[\s>/]", data)):
        s = m.start()
        e_open = data.find(b">", s)
        if e_open < 0:
            break
        if data[e_open - 1:e_open] == b"/":
            end = e_open + 1
        else:
            end = data.find(b"</flame>", e_open)
            if end < 0:
                break
            end += len(b"</flame>")
        head = data[s:e_open]
        out.append((i, writer(head, jwf_root), data[s:end]))
    return out


def writer(head, jwf_root):
    if jwf_root:
        return "jwildfire"
    v = (attr(head, "version") or "").strip()
    lv = v.lower()
    if lv.startswith("jwildfire"):
        return "jwildfire"
    if re.match(r"0\.\d+ \(\d\d\.\d\d\.\d{4}\)", v):
        return "jwildfire-2011"
    if lv.startswith("apophysis"):
        return "apophysis"
    if lv.startswith("ember"):
        return "fractorium"
    if "flam3h" in lv:
        return "flam3h"
    if lv.startswith("fr0st"):
        return "fr0st"
    if lv.startswith("flam3") or not v:
        name = (attr(head, "name") or "").lower()
        return "electricsheep" if name.startswith("electricsheep") else "flam3"
    return "unknown:" + v[:20]


def resized(text, width, quality):
    """The flame rewritten to `width` px (height from its aspect, pixels per unit scaled with
    the width) and `quality`, and its height."""
    head_end = text.find(b">")
    head = text[:head_end]
    m = re.search(rb'\ssize="([0-9.]+) ([0-9.]+)"', head)
    w0, h0 = (float(m.group(1)), float(m.group(2))) if m else (100.0, 100.0)
    height = max(1, round(width * h0 / w0))
    k = width / w0
    new = re.sub(rb'\ssize="[^"]*"', b"", head)
    new = re.sub(rb'\squality="[^"]*"', b"", new)

    def scaled(mm):
        return b' scale="%r"' % (float(mm.group(1)) * k)

    new = re.sub(rb'\sscale="([-0-9.eE+]+)"', scaled, new, count=1)
    new += b' size="%d %d" quality="%g"' % (width, height, quality)
    return new + text[head_end:], height


def cached(cache, key, render):
    out = os.path.join(cache, key + ".png")
    fail = out + ".fail"
    if os.path.exists(out):
        return out, None
    if os.path.exists(fail):
        return None, open(fail).read()
    note = render(out)
    if note is None and os.path.exists(out):
        return out, None
    with open(fail, "w") as f:
        f.write(note or "no picture")
    return None, note


def reference(program, one, src, index, out, w, h, quality, threads, seed):
    """Renders with the reference program; None when it worked, else why not."""
    if program == "flam3":
        try:
            f3.flam3(one, out, threads, isaac_seed=f"corpus{seed}")
        except subprocess.CalledProcessError as e:
            return "flam3-render: " + (e.stderr or b"").decode("utf-8", "replace").strip()[-70:]
        return None
    if program == "ember":
        _, r = fr.ember(one, 0, out, w, h, quality, threads)
        if r.returncode != 0:
            return "emberrender: " + ((r.stderr.strip().splitlines() or ["?"])[-1])[:70]
        return None
    ok, note = jw.jwildfire(src, index, out, w, h, quality, seed)
    return None if ok else "JWildfire: " + note[:70]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="*", help="flame files or folders (default: both test corpora)")
    ap.add_argument("--width", type=int, default=160)
    ap.add_argument("--quality", type=float, default=200)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--only", default=None, help="only files whose name contains this")
    ap.add_argument("--writer", default=None, help="only this writer (flam3, electricsheep, apophysis, …)")
    ap.add_argument("--margin", type=float, default=3.0, help="dB below the reference's noise that count")
    ap.add_argument("--ugnis-rule", default=None,
                    help="palette rule ugnis uses for every flame (flam3, apophysis, fractorium, jwildfire)")
    ap.add_argument("--cache", default=os.path.join(tempfile.gettempdir(), "ugnis-corpus-cache"))
    ap.add_argument("--keep", default=None, help="directory to keep each flame's pictures in")
    a = ap.parse_args()
    if not os.path.exists(jw.UGNIS):
        sys.exit(f"{jw.UGNIS} missing: cargo build --release")
    have = {"flam3": shutil.which("flam3-render") is not None,
            "ember": os.path.exists(os.path.join(fr.EMBER_HOME, "bin", "emberrender")),
            "jwildfire": os.path.exists(os.path.join(os.environ.get("JWF_HOME", "/tmp/jwildfire"),
                                                     "classpath.txt"))}
    os.makedirs(a.cache, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="ugnis-corpus-")
    jobs = []
    for f in jw.flame_files(a.inputs or jw.DEFAULT_INPUTS):
        if a.only and a.only not in os.path.basename(f):
            continue
        for i, wr, text in flames(f):
            if wr == "jwildfire" or (a.writer and wr != a.writer):
                continue
            jobs.append((f, i, wr, text))
    print(f"{len(jobs)} flames, {a.width} px wide, quality {a.quality:g}")
    print(f"{'flame':<60} {'writer':<14} {'ugnis':>6} {'noise':>6}  notes")
    rows, refused = [], []
    for f, i, wr, text in jobs:
        name = f"{os.path.basename(f)[-56:]}#{i}"
        program = PROGRAM.get(wr)
        if program is None or not have[program]:
            refused.append((name, wr, f"no reference program for {wr}"))
            continue
        one_text, h = resized(text, a.width, a.quality)
        ext = os.path.splitext(f)[1]
        one = os.path.join(tmp, "one" + ext)
        with open(one, "wb") as fh:
            fh.write(b'<?xml version="1.0" encoding="UTF-8"?>\n<flames>\n' + one_text + b"\n</flames>\n")
        key = hashlib.sha1(one_text + program.encode()).hexdigest()[:16]
        refs = []
        note = None
        for seed in (1, 2):
            # The 2011 JWildfire files go to JWildfire as they are, with their index.
            r, note = cached(a.cache, f"{key}-s{seed}",
                             lambda out, s=seed: reference(program, one, f, i, out, a.width, h,
                                                           a.quality, a.threads, s))
            if r is None:
                break
            refs.append(r)
        if len(refs) < 2:
            refused.append((name, wr, note or "?"))
            print(f"{name:<60} {wr:<14} refused: {(note or '?')[:60]}", flush=True)
            continue
        src = one
        if a.ugnis_rule:
            data = re.sub(rb'\sugnis_palette_index="[^"]*"', b"", open(one, "rb").read())
            data = re.sub(rb"<flame(\s|>)", b'<flame ugnis_palette_index="' + a.ugnis_rule.encode() + b'"\\1',
                          data, count=1)
            src = os.path.join(tmp, "ruled" + ext)
            open(src, "wb").write(data)
        ug = os.path.join(tmp, "ug.png")
        # JWildfire's reference draws at oversampling 1 (see compare_jwildfire.py); flam3-render
        # and emberrender keep the file's supersample, as ugnis does.
        ss = 1 if program == "jwildfire" else None
        r = jw.ugnis(src, 0, ug, a.width, h, a.quality, a.threads, supersample=ss)
        if r.returncode != 0:
            msg = (r.stderr.strip().splitlines() or ["?"])[-1][:60]
            refused.append((name, wr, f"ugnis: {msg}"))
            print(f"{name:<60} {wr:<14} refused by ugnis: {msg}", flush=True)
            continue
        R = jw.load(refs[0])
        p, pn = jw.psnr(jw.load(ug), R), jw.psnr(jw.load(refs[1]), R)
        miss = jw.missing_variations(r.stderr)
        rows.append((name, wr, p, pn, miss))
        line = f"{name:<60} {wr:<14} {p:6.2f} {pn:6.2f}"
        if p < pn - a.margin:
            line += f"  below noise by {pn - p:.1f}"
        if miss:
            line += "  missing: " + ",".join(miss)
        print(line, flush=True)
        if a.keep:
            os.makedirs(a.keep, exist_ok=True)
            stem = re.sub(r"[^A-Za-z0-9_.-]", "_", f"{os.path.basename(f)}-{i}")
            os.replace(ug, os.path.join(a.keep, f"{stem}.ug.png"))
            shutil.copy(refs[0], os.path.join(a.keep, f"{stem}.ref.png"))
            shutil.copy(refs[1], os.path.join(a.keep, f"{stem}.ref2.png"))
    print()
    print(f"{'writer':<16} {'program':<10} {'flames':>6} {'ugnis':>7} {'noise':>7} {'below':>6}")
    for wr in sorted({r[1] for r in rows}) + ["all"]:
        sel = [r for r in rows if wr == "all" or r[1] == wr]
        below = sum(1 for r in sel if r[2] < r[3] - a.margin)
        print(f"{wr:<16} {PROGRAM.get(wr, ''):<10} {len(sel):6d} {statistics.median(r[2] for r in sel):7.2f} "
              f"{statistics.median(r[3] for r in sel):7.2f} {below:6d}")
    print(f"(medians in dB; below: ugnis more than {a.margin:g} dB under the reference's own noise)")
    print(f"refused: {len(refused)}")
    for n, wr, why in refused:
        print(f"  {n} ({wr}): {why[:90]}")


if __name__ == "__main__":
    main()
