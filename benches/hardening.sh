#!/usr/bin/env bash
# The hostile inputs of the hardening pass, timed: wall time, peak memory (max RSS) and exit
# code of each case. Every case must end within seconds, under 1 GiB, with exit 0 (a correct
# result) or 1 (one clear message), and write nothing but its output.
#
# Usage: benches/hardening.sh [path/to/ugnis]     (default: target/release/ugnis; build it
#        with `cargo build --release --no-default-features` first)
# Needs /usr/bin/time (Debian package `time`) and python3.
set -uo pipefail
cd "$(dirname "$0")/.."
UGNIS=${1:-target/release/ugnis}
UGNIS=$(realpath "$UGNIS")
JUG=$(realpath examples/jug.toml)
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
cd "$W"

printf '%-58s %8s %10s %5s\n' "case" "seconds" "max RSS" "exit"
run() {
  local name=$1
  shift
  /usr/bin/time -f '%e %M' -o time.txt "$@" >out.txt 2>err.txt
  local code=$?
  read -r secs kib < <(tail -1 time.txt)
  printf '%-58s %8s %7s MiB %5s   %s\n' "$name" "$secs" "$((kib / 1024))" "$code" \
    "$(grep -v '^ *Command exited' err.txt | head -1 | cut -c1-110)"
}

# Inputs, generated.
printf 'kind = mandelbrot\nsize = 30000x30000\n' >big.esc
python3 - <<'EOF'
import zlib, struct
def png(w, h, path):
    raw = b''.join(b'\0' + b'\xff\0\0' * w for _ in range(h))
    def chunk(t, d):
        c = struct.pack('>I', len(d)) + t + d
        return c + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    open(path, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
                           + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
png(1, 1100000, 'tall.png')
png(1100000, 1, 'wide.png')
def flame(n_attrs, path):
    attrs = ''.join(f' plugin_p{k}="{k}"' for k in range(n_attrs))
    open(path, 'w').write(f'<flame name="a" size="64 48"><xform weight="1" linear="1"{attrs}/></flame>\n')
flame(60000, 'attrs60k.flame')
flame(1000000, 'attrs1m.flame')
open('q.flame', 'w').write('<flame name="q" size="64 48" scale="10" quality="1e12"><xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/><xform weight="1" linear="1" coefs="0.5 0 0 0.5 1 0"/></flame>\n')
open('ok.flame', 'w').write('<flame name="ok" size="64 48" scale="10" quality="20"><xform weight="1" linear="1" coefs="0.5 0 0 0.5 0 0"/><xform weight="1" linear="1" coefs="0.5 0 0 0.5 1 0"/></flame>\n')
prof = ', '.join(f'[{1 + (k % 3) * 0.1}, {k * 0.001}]' for k in range(30001))
open('rev10k.toml', 'w').write(f'[[object]]\nkind = "revolve"\nprofile = [{prof}]\n')
prof = ', '.join(f'[{1 + (k % 3) * 0.1}, {k * 0.001}]' for k in range(3001))
open('rev1k.toml', 'w').write(f'[[object]]\nkind = "revolve"\nprofile = [{prof}]\n')
open('objs800k.toml', 'w').write('[[object]]\nkind = "jug"\n' * 800000)
open('objs1250.toml', 'w').write('[[object]]\nkind = "jug"\n' * 1250)
open('objs1251.toml', 'w').write('[[object]]\nkind = "jug"\n' * 1251)
open('stereo.toml', 'w').write('[camera]\nprojection = "stereo"\n[[object]]\nkind = "jug"\n')
open('big.ugr', 'w').write(''.join(f'g{k} {{\ngradient:\n index=0 color={k}\n}}\n' for k in range(10000)))
open('long.map', 'w').write(''.join(f'{k % 256} 0 0\n' for k in range(10000)))
EOF
ln -s /dev/zero zero.flame
mkfifo fifo.flame

run "escape --view (size 30000x30000)" "$UGNIS" escape --view big.esc -o e.png
run "scene jug --size 100000x100000" "$UGNIS" scene "$JUG" --size 100000x100000 -o s.png
run "scene jug --size 16000x16000 --supersample 4" "$UGNIS" scene "$JUG" --size 16000x16000 --supersample 4 -o s.png
run "scene: revolve with 10,000 segments" "$UGNIS" scene rev10k.toml -o s.png
run "scene: revolve with 1,000 segments (the limit)" "$UGNIS" scene rev1k.toml -o s.png --size 320x240
run "scene: 800,000 objects" "$UGNIS" scene objs800k.toml -o s.png
run "scene: 1,250 jugs (25,000 patches, the limit), 320x240" "$UGNIS" scene objs1250.toml -o s.png --size 320x240
run "scene: 1,251 jugs" "$UGNIS" scene objs1251.toml -o s.png --size 320x240
run "convert tall.png (1x1,100,000) g.ugr" "$UGNIS" convert tall.png g.ugr
run "convert wide.png (1,100,000x1) g.map" "$UGNIS" convert wide.png g.map
run "escape --gradient tall.png" "$UGNIS" escape mandelbrot --gradient tall.png --size 64x48 -o e.png
run "render --threads 100000 (64x48)" "$UGNIS" render ok.flame --threads 100000 -o r.png
run "escape --threads 10000 (64x48)" "$UGNIS" escape julia --threads 10000 --size 64x48 -o e.png
run "scene --threads 100000 (64x48)" "$UGNIS" scene "$JUG" --threads 100000 --size 64x48 -o s.png
run "scene stereo --size 1x48" "$UGNIS" scene stereo.toml --size 1x48 -o s.png
run "info big.ugr | head -1" sh -c "'$UGNIS' info big.ugr | head -1"
run "info: 60,000 attributes" "$UGNIS" info attrs60k.flame
run "info: 1,000,000 attributes" "$UGNIS" info attrs1m.flame
run "render --quality 1e12" "$UGNIS" render ok.flame --quality 1e12 -o r.png
run "render quality=\"1e12\" in the file" "$UGNIS" render q.flame -o r.png
run "render --quality 1e-300" "$UGNIS" render ok.flame --quality 1e-300 -o r.png
run "info symlink to /dev/zero" "$UGNIS" info zero.flame
run "info FIFO" timeout 10 "$UGNIS" info fifo.flame
run "random --count 10000 --min-xforms 100 --variation mix" "$UGNIS" random --count 10000 --min-xforms 100 --max-xforms 100 --variation mix -o r.fla
run "random --count 2000 --min-xforms 100 --max-xforms 100" "$UGNIS" random --count 2000 --min-xforms 100 --max-xforms 100 --seed 1 -o r.fla
run "info of that batch ($(($(stat -c %s r.fla 2>/dev/null || echo 0) >> 20)) MiB)" "$UGNIS" info r.fla
run "escape --offset nan --save-view v.esc" "$UGNIS" escape mandelbrot --offset nan --save-view v.esc -o e.png
run "info long.map (10,000 lines)" "$UGNIS" info long.map
run "render -o missing/dir/x.png (checked first)" "$UGNIS" render ok.flame --quality 100000 --size 2000x2000 -o missing/dir/x.png
echo
echo "files left in the work directory besides the inputs and outputs:"
ls -a | grep -i 'ugnis-tmp' || echo "  none"
