#!/usr/bin/env bash
# The hostile inputs of the hardening pass, timed: wall time, peak memory (max RSS) and exit
# code of each case. Every case must end within seconds, under 1 GiB, with exit 0 (a correct
# result) or 1 (one clear message), and write nothing but its output.
#
# Usage: benches/hardening.sh [path/to/ugnis]     (default: target/release/ugnis; build it
#        with `cargo build --release --no-default-features` first)
#        FUZZ=1 benches/hardening.sh  also runs the full variation fuzz (every variation, every
#        parameter, every extreme value: minutes) through `cargo test -- --ignored`.
# Needs /usr/bin/time (Debian package `time`) and python3.
set -uo pipefail
cd "$(dirname "$0")/.."
SRC=$PWD
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

# Outputs that are not the command's to replace, signals, parameters that hang, stderr that
# cannot be written, readers at their limits, strips under an address-space limit, batches.
python3 - <<'EOF'
entry = lambda k: f'e{k} {{\n .5 0 0 .5 0 0 .33\n}}\n'
open('e50k.ifs', 'w').write(''.join(entry(k) for k in range(50000)))
open('e10k.ifs', 'w').write(''.join(entry(k) for k in range(10000)))
def var_flame(path, attrs):
    open(path, 'w').write(f'<flame name="v" size="64 48" scale="10" quality="5"><xform weight="1" {attrs} coefs="0.5 0 0 0.5 0 0"/><xform weight="1" linear="1" coefs="0.5 0 0 0.5 1 0"/></flame>\n')
var_flame('nblur.flame', 'nBlur="1" nBlur_numEdges="1e308" nBlur_numStripes="1e9"')
var_flame('snow.flame', 'snowflake_wf="1" snowflake_wf_buffer_size="1e9" snowflake_wf_max_iter="1e9"')
var_flame('dla.flame', 'dla3d_wf="1" dla3d_wf_max_iter="1e9" dla3d_wf_glue_radius="0"')
var_flame('bubble.flame', 'bubbleT3D="1" bubbleT3D_number_of_stripes="1e308"')
var_flame('mandel.flame', 'mandelbrot="1" mandelbrot_iter="1e9"')
var_flame('prepost.flame', 'post_smartcrop="0.5" pre_blur="0.1" blur="0.2"')
EOF
mknod dev.ugs c 1 3 2>/dev/null
mkfifo pipe.ugs
run "render --save-state dev.ugs (a device node)" "$UGNIS" render ok.flame -o r.png --save-state dev.ugs
run "render --save-state pipe.ugs (a named pipe)" "$UGNIS" render ok.flame -o r.png --save-state pipe.ugs
cp ok.flame in.flame
run "render in.flame --save-state in.flame" "$UGNIS" render in.flame -o r.png --save-state in.flame
run "render -o same.png --save-state same.png" "$UGNIS" render ok.flame -o same.png --save-state same.png
# A signal `wait` seconds into a command: its exit code, how long it took to stop, what it left.
# (Sent by timeout: a job put in the background by a script starts with SIGINT ignored.)
signal_case() {
  local name=$1 sig=$2 wait=$3
  shift 3
  rm -f sig.png sig.ugs
  local t0
  t0=$(date +%s%N)
  timeout --preserve-status -s "$sig" "$wait" "$@" >out.txt 2>err.txt
  local code=$?
  local ms=$((($(date +%s%N) - t0) / 1000000 - wait * 1000))
  printf '%-58s %8s %10s %5s   %s\n' "$name" "" "" "$code" \
    "stopped ${ms} ms after the signal; outputs: $(ls sig.* 2>/dev/null | wc -l), temporary files: $(ls -a | grep -c ugnis-tmp)"
}
signal_case "SIGINT during a render with --save-state" INT 3 \
  "$UGNIS" render ok.flame --size 2000x2000 --quality 2000 -o sig.png --save-state sig.ugs
signal_case "SIGTERM during the iteration" TERM 2 \
  "$UGNIS" render ok.flame --size 2000x2000 --quality 2000 -o sig.png
signal_case "SIGHUP during the iteration" HUP 2 \
  "$UGNIS" render ok.flame --size 2000x2000 --quality 2000 -o sig.png
run "render nBlur_numEdges=1e308" timeout 120 "$UGNIS" render nblur.flame -o v.png
run "render snowflake_wf buffer_size, max_iter 1e9" timeout 120 "$UGNIS" render snow.flame -o v.png
run "render dla3d_wf max_iter 1e9, glue_radius 0" timeout 120 "$UGNIS" render dla.flame -o v.png
run "render bubbleT3D_number_of_stripes=1e308" timeout 120 "$UGNIS" render bubble.flame -o v.png
run "render mandelbrot_iter=1e9" timeout 120 "$UGNIS" render mandel.flame -o v.png
run "post_smartcrop + pre_blur + blur: render, then info of the PNG" \
  sh -c "'$UGNIS' render prepost.flame -o pp.png && '$UGNIS' info pp.png"
run "render with stderr on /dev/full (warnings dropped)" \
  sh -c "'$UGNIS' render nblur.flame -o v.png 2>/dev/full"
run "info: .ifs of 10,000 entries (the limit)" "$UGNIS" info e10k.ifs
run "info: .ifs of 50,000 entries" "$UGNIS" info e50k.ifs
run "render 8000x6000 under prlimit --as=1.5 GiB (strips)" \
  prlimit --as=$((3 << 29)) "$UGNIS" render ok.flame --size 8000x6000 --quality 0.2 -o poster.png
mkdir -p b.fla
run "random --thumbs with an unwritable batch" \
  "$UGNIS" random --count 4 --size 16x16 --quality 1 --thumbs t -o b.fla
echo "  thumbnails left after the failed batch: $(ls t 2>/dev/null | wc -l)"
run "animate --frames 10000000 (Ctrl+C after 20 s)" \
  timeout -s INT 20 "$UGNIS" animate ok.flame --frames 10000000 --size 32x24 -o frames
grep -h "will take" err.txt | cut -c1-150 | sed 's/^/  /'
if [ "${FUZZ:-0}" = 1 ]; then
  echo
  echo "every variation x every parameter x +-1e308, +-1e9, -1, 0, 1e-300, NaN:"
  (cd "$SRC" && cargo test --test hardening extreme_parameters -- --ignored --nocapture 2>&1 |
    grep -E "cases over|^  [a-zA-Z]|test result")
fi

echo
echo "files left in the work directory besides the inputs and outputs:"
ls -a | grep -i 'ugnis-tmp' || echo "  none"
