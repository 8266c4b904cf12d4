#!/usr/bin/env bash
# Posters and render farms, measured (numbers for the notes; run by hand, not in CI):
#   1. peak RSS of a poster rendered in strips under a 2 GiB limit;
#   2. four single-thread parts in four processes plus the merge, against one single-thread
#      render of the whole quality;
#   3. merge time of four 4000x3000 states;
#   4. state size against the raw accumulator (16 bytes a bucket).
# Usage: benches/farm.sh [POSTER_SIZE] (default 20000x15000; pass a smaller size on a small
# machine: the strip height, and so the memory, depends on the width and the budget).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${UGNIS:-}" ]; then
  cargo build --release --no-default-features -q
fi
U=${UGNIS:-$PWD/target/release/ugnis}
F=$PWD/examples/orchid.flame
POSTER=${1:-20000x15000}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
secs() { /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1; }

echo "== 1. poster $POSTER in strips, --memory-limit 2G, quality ${POSTER_QUALITY:-1}"
/usr/bin/time -f "wall %e s, peak RSS %M KiB" "$U" render "$F" --size "$POSTER" \
  --quality "${POSTER_QUALITY:-1}" --memory-limit 2G --threads 2 -o "$T/poster.png" --progress none

echo "== 2. four parts (one thread each, four processes) + merge vs one single-thread render"
S=${PART_SIZE:-1600x1200}
Q=${PART_QUALITY:-50}
one=$(secs "$U" render "$F" --size $S --quality $Q --threads 1 -o "$T/one.png" --progress none)
start=$(date +%s.%N)
for i in 0 1 2 3; do
  "$U" render "$F" --size $S --quality $Q --threads 1 --part $i/4 \
    --save-state "$T/p$i.ugnis-state" --progress none &
done
wait
mid=$(date +%s.%N)
"$U" merge "$T"/p?.ugnis-state -o "$T/merged.png" --progress none
end=$(date +%s.%N)
echo "single thread: $one s; parts: $(echo "$mid - $start" | bc) s; merge: $(echo "$end - $mid" | bc) s;" \
  "ratio $(echo "scale=3; ($end - $start) / $one" | bc) on $(nproc) cores"

echo "== 3. merge of four 4000x3000 states (quality ${MERGE_QUALITY:-20} in all)"
for i in 0 1 2 3; do
  "$U" render "$F" --size 4000x3000 --quality ${MERGE_QUALITY:-20} --part $i/4 \
    --save-state "$T/m$i.ugnis-state" --progress none
done
echo "merge: $(secs "$U" merge "$T"/m?.ugnis-state -o "$T/m.png" --progress none) s"
echo "merge + merged state: $(secs "$U" merge "$T"/m?.ugnis-state -o "$T/m.png" --save-state "$T/all.ugnis-state" --progress none) s"

echo "== 4. state size vs raw accumulator"
"$U" info "$T/m0.ugnis-state" | grep histogram
"$U" info "$T/all.ugnis-state" | grep histogram
for q in 200; do
  "$U" render "$F" --size 4000x3000 --quality $q --save-state "$T/q$q.ugnis-state" --progress none
  echo "quality $q: $("$U" info "$T/q$q.ugnis-state" | grep histogram)"
done
