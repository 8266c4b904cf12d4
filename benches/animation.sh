#!/usr/bin/env bash
# Animation speed against flam3-animate, side by side in one run (run by hand, not in CI):
#   1. motion-blurred frames (temporal_samples 1000) of a flam3-genome sequence, 640x480,
#      quality 200, 2 threads: best-of-N wall time of `ugnis animate` and of flam3-animate for a
#      rotation frame (time 3) and a transition frame (time 14), and their ratio
#      (target ≤ 0.5, moonshot 0.25);
#   2. a 300-frame 640x480 loop (flam3-genome's loops and transitions of two flames) to MP4,
#      the whole `ugnis animate … -o loop.mp4` process, at quality LOOP_QUALITY (default 50).
# Needs flam3-utils and ffmpeg. Usage: benches/animation.sh [N] (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${UGNIS:-}" ]; then
  cargo build --release --no-default-features -q
fi
U=${UGNIS:-$PWD/target/release/ugnis}
N=${1:-3}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
# The fixture pair is 160x120: flam3-animate scales it with ss=4, ugnis with --size.
env sequence=tests/fixtures/animation/pair.flam3 nframes=10 flam3-genome >"$T/seq.flam3" 2>/dev/null
best() { sort -n | head -1; }
wall() { /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1; }
echo "== 1. motion-blurred frames, 640x480, quality 200, temporal_samples 1000, 2 threads (best of $N)"
for t in 3 14; do
  : >"$T/u" && : >"$T/f"
  for _ in $(seq "$N"); do
    rm -rf "$T/o" && mkdir "$T/o"
    wall "$U" animate "$T/seq.flam3" --frames "$t..$t" -o "$T/o" --size 640x480 --threads 2 >>"$T/u"
    wall env in="$T/seq.flam3" begin="$t" end="$t" prefix="$T/o/f3-" nthreads=2 ss=4 verbose=0 \
      flam3-animate >>"$T/f"
  done
  u=$(best <"$T/u") f=$(best <"$T/f")
  echo "time $t: ugnis $u s, flam3-animate $f s, ratio $(awk -v u="$u" -v f="$f" 'BEGIN { printf "%.2f", u / f }')"
done
LQ=${LOOP_QUALITY:-50}
echo "== 2. 300-frame 640x480 loop to MP4 (quality $LQ, 2 threads, whole process)"
/usr/bin/time -f "wall %e s, peak RSS %M KiB" "$U" animate tests/fixtures/animation/pair.flam3 \
  --mode loop --loop-frames 75 --size 640x480 --quality "$LQ" --threads 2 -o "$T/loop.mp4"
echo "frames: $(ls "$T/loop.mp4.frames" | wc -l), video: $(stat -c %s "$T/loop.mp4") bytes"
