#!/usr/bin/env bash
# `ugnis thumbnail IN OUT 256` as a file manager runs it: the whole process (start, read,
# render, write) for every example flame, IFS, gradient list and escape-time view, best of N
# runs each (best of N filters out the runs a busy machine slowed down). Goal: ≤ 0.3 s each.
# Usage: benches/thumbnail.sh [SIZE] [N]   (default 256 5; UGNIS=path/to/ugnis to skip the build)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${UGNIS:-}" ]; then
  cargo build --release --no-default-features -q
fi
U=${UGNIS:-$PWD/target/release/ugnis}
SIZE=${1:-256}
N=${2:-5}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
files=(examples/*.flame examples/*.fla examples/*.esc tests/fixtures/library.ifs tests/fixtures/hand.ugr)
worst=0
printf '%-40s %8s %8s\n' file "best s" "CPU s"
for f in "${files[@]}"; do
  [ -e "$f" ] || continue
  best=""
  cpu=""
  for _ in $(seq "$N"); do
    /usr/bin/time -f "%e %U %S" -o "$T/t" "$U" thumbnail "$f" "$T/out.png" "$SIZE" 2>/dev/null \
      || { echo "$f: failed" >&2; continue 2; }
    read -r e u s < "$T/t"
    if [ -z "$best" ] || awk -v a="$e" -v b="$best" 'BEGIN{exit !(a<b)}'; then
      best=$e
      cpu=$(awk -v u="$u" -v s="$s" 'BEGIN{printf "%.2f", u+s}')
    fi
  done
  printf '%-40s %8s %8s\n' "$f" "$best" "$cpu"
  worst=$(awk -v a="$best" -v b="$worst" 'BEGIN{print (a>b)?a:b}')
done
echo "slowest: $worst s (goal ≤ 0.3 s): $(awk -v w="$worst" 'BEGIN{print (w<=0.3)?"met":"missed"}')"
