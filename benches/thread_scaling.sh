#!/usr/bin/env bash
# Two threads against one (target: ≥ 1.85×), measured so that a noisy machine
# can be told apart from a serial part of the program:
#   - wall ratio: best one-thread wall time / best two-thread wall time, over N runs that
#     alternate (best of N filters out the runs the machine slowed down);
#   - CPUs used by the two-thread render (user + system time / wall time): below 2 only by the
#     parts that do not run in parallel, whatever the machine does;
#   - CPU time of the two-thread render against the one-thread one: above 1 when the two
#     cores slow each other down (shared caches, memory, or one host core for both vCPUs).
# Usage: benches/thread_scaling.sh [FLAME] [SIZE] [QUALITY] [N]
#        (default examples/sierpinski.flame 640x480 500 8)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${UGNIS:-}" ]; then
  cargo build --release --no-default-features -q
fi
U=${UGNIS:-$PWD/target/release/ugnis}
F=${1:-examples/sierpinski.flame}
SIZE=${2:-640x480}
Q=${3:-500}
N=${4:-8}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
for _ in $(seq "$N"); do
  for t in 1 2; do
    /usr/bin/time -f "$t %e %U %S" -a -o "$T/times" "$U" render "$F" -o "$T/out.png" \
      --size "$SIZE" --quality "$Q" --threads "$t" --progress none 2>/dev/null
  done
done
awk '
  { cpu = $3 + $4
    if (!($1 in best) || $2 < best[$1]) best[$1] = $2
    wall[$1] += $2; used[$1] += cpu; n[$1]++ }
  END {
    printf "one thread: best %.2f s, mean %.2f s; two threads: best %.2f s, mean %.2f s\n",
      best[1], wall[1] / n[1], best[2], wall[2] / n[2]
    printf "wall ratio (best of %d): %.2fx; CPUs used by two threads: %.2f; CPU time two/one: %.2f\n",
      n[1], best[1] / best[2], used[2] / wall[2], used[2] / used[1]
  }' "$T/times"
