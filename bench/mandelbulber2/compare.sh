#!/usr/bin/env bash
# Side by side with Mandelbulber2 (2.20, Debian's package, CPU renderer): the power-8 Mandelbulb with
# a soft shadow, AO and a specular highlight at a matched look, 1024x1024, on this machine's CPU
# (Fractograph on Mesa's lavapipe).
#
#   bash bench/mandelbulber2/compare.sh [OUT_DIR]        (default docs/bench/mandelbulber2)
#   REPEATS=3 SIZE=1024 FG_BUILD_DIR=build  (environment, defaults shown; or FGC=... FGPLAY=...;
#   KEEP_WORK=DIR keeps the pictures and times there: a later run with the same DIR reuses its
#   16-sample references and adds its runs to the table; ROWS="fast multiray" picks the rows,
#   SAMPLES="1 4" the sample counts, REF=0 skips the references and so the PSNR, REF_SAMPLES=16 their
#   samples a pixel (a square), AREA=0 Fractograph's soft shadow: 0 its cone-angle penumbra in every
#   sample, deterministic as Mandelbulber2's; 1 the area light, a point of the disc a sample)
#
# Two rows, one per AO method:
#   fast AO       Mandelbulber2 ambient_occlusion_mode 0 (quality 4: 15 distance samples along the normal)
#                 against graphs/examples/lit_mandelbulb.json (light.fake_ao, one sample)
#   multi-ray AO  Mandelbulber2 ambient_occlusion_mode 1 (quality 2: 29 rays over the sphere, about half
#                 of them above the surface) against bench/mandelbulber2/mandelbulb_lit_marched_ao.json
#                 (light.marched_ao, 16 cones of up to 24 steps)
# Both tools are deterministic here (no Monte Carlo shadows or AO; with AREA=1 Fractograph's shadow
# is), so "matched noise" means matched anti-aliasing: Mandelbulber2's antialiasing_size N (N x N
# samples a pixel) against fgplay render --samples N^2, at 1 and 4 samples a pixel. The error of each
# picture is its PSNR against the same tool's own REF_SAMPLES picture (antialiasing_size 4,
# --samples 16 by default), so each tool is judged by how close it comes to its own converged image.
# Timing: wall time and CPU time (user + sys) of each whole command, start-up and PNG writing
# included, REPEATS times, the two tools alternating, medians reported. fgplay render always renders
# a stereo pair (two 1024x1024 eyes, same work each: these scenes shade every hit themselves); the
# table gives the pair and half of it as the time of one picture.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
HERE=$ROOT/bench/mandelbulber2
OUT=${1:-$ROOT/docs/bench/mandelbulber2}
BUILD=${FG_BUILD_DIR:-$ROOT/build}
FGC=${FGC:-$BUILD/compiler/fgc}
FGPLAY=${FGPLAY:-$BUILD/runtime/fgplay}
REPEATS=${REPEATS:-3}
SIZE=${SIZE:-1024}
SAMPLES=${SAMPLES:-1 4}
REF=${REF:-1}
REF_SAMPLES=${REF_SAMPLES:-16}
AREA=${AREA:-0}
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$BUILD/mesa-cache}
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
MB2=${MB2:-mandelbulber2}
WORK=${KEEP_WORK:-$(mktemp -d)}   # KEEP_WORK=DIR keeps every picture there
[ -n "${KEEP_WORK:-}" ] && mkdir -p "$WORK" || trap 'rm -rf "$WORK"' EXIT

for tool in "$FGC" "$FGPLAY"; do
  [ -x "$tool" ] || { echo "missing $tool: build first (bash scripts/fractograph.sh build)"; exit 1; }
done
command -v "$MB2" >/dev/null || { echo "missing mandelbulber2: apt-get install --no-install-recommends mandelbulber2"; exit 1; }
mkdir -p "$OUT"

# row -> Mandelbulber2 overrides and Fractograph graph
declare -A MB_AO=([fast]="ambient_occlusion_mode=0#ambient_occlusion_quality=4"
                  [multiray]="ambient_occlusion_mode=1#ambient_occlusion_quality=2")
declare -A FG_GRAPH=([fast]="$ROOT/graphs/examples/lit_mandelbulb.json"
                     [multiray]="$HERE/mandelbulb_lit_marched_ao.json")
ROWS=${ROWS:-fast multiray}
for row in $ROWS; do
  # The graph with its soft shadow's "area" set to AREA.
  /usr/bin/python3 - "${FG_GRAPH[$row]}" "$WORK/$row.json" "$AREA" <<'PY'
import json, sys
graph = json.load(open(sys.argv[1]))
for node in graph["nodes"]:
    if node["type"] == "light.soft_shadow":
        node.setdefault("inputs", {})["area"] = sys.argv[3] == "1"
json.dump(graph, open(sys.argv[2], "w"))
PY
  "$FGC" compile "$WORK/$row.json" -o "$WORK/$row.fgpack" >/dev/null
done

mb_aa() {  # samples -> Mandelbulber2 anti-aliasing overrides
  local n; n=$(/usr/bin/python3 -c "import math; print(math.isqrt($1))")
  # (--override takes 1 and 0 for booleans; "true" is ignored there)
  if [ "$n" -le 1 ]; then echo "antialiasing_enabled=0"; else echo "antialiasing_enabled=1#antialiasing_size=$n"; fi
}
run_mb() {  # row samples tag -> image $WORK/mb-ROW-SAMPLES-TAG.png, times appended to $WORK/times.csv
  local row=$1 s=$2 tag=$3 img=$WORK/mb-$1-$2-$3.png
  /usr/bin/time -o "$WORK/t" -f '%e %U %S' nice -n 5 "$MB2" --nogui --format png --res "${SIZE}x${SIZE}" \
    -O "${MB_AO[$row]}#$(mb_aa "$s")" --output "$img" "$HERE/mandelbulb_lit.fract" >"$WORK/mb.log" 2>&1
  read -r wall user sys <"$WORK/t"
  echo "mandelbulber2,$row,$s,$tag,$wall,$(echo "$user + $sys" | bc)" >>"$WORK/times.csv"
}
run_fg() {  # row samples tag -> image $WORK/fg-ROW-SAMPLES-TAG.png (left eye)
  local row=$1 s=$2 tag=$3
  /usr/bin/time -o "$WORK/t" -f '%e %U %S' nice -n 5 "$FGPLAY" render "$WORK/$row.fgpack" \
    --out "$WORK/fg-out" --size "${SIZE}x${SIZE}" --samples "$s" >"$WORK/fg.log" 2>&1
  cp "$WORK/fg-out/left.png" "$WORK/fg-$row-$s-$tag.png"
  read -r wall user sys <"$WORK/t"
  echo "fractograph,$row,$s,$tag,$wall,$(echo "$user + $sys" | bc)" >>"$WORK/times.csv"
}

touch "$WORK/times.csv"
# One warm-up run each (shader caches, page cache), not counted; then the references.
for row in $ROWS; do
  echo "==> $row: warm-up and $REF_SAMPLES-sample references"
  run_fg "$row" 1 warm; run_mb "$row" 1 warm
  if [ "$REF" = 1 ]; then
    [ -s "$WORK/mb-$row-$REF_SAMPLES-ref.png" ] || run_mb "$row" "$REF_SAMPLES" ref
    [ -s "$WORK/fg-$row-$REF_SAMPLES-ref.png" ] || run_fg "$row" "$REF_SAMPLES" ref
  fi
done
for r in $(seq 1 "$REPEATS"); do
  for row in $ROWS; do
    for s in $SAMPLES; do
      echo "==> repeat $r/$REPEATS: $row, $s sample(s) a pixel"
      if [ $((r % 2)) = 1 ]; then run_mb "$row" "$s" "r$r"; run_fg "$row" "$s" "r$r"
      else run_fg "$row" "$s" "r$r"; run_mb "$row" "$s" "r$r"; fi
    done
  done
done

# Table, error figures and the side-by-side picture.
/usr/bin/python3 - "$WORK" "$OUT" "$REPEATS" "$SIZE" "$REF_SAMPLES" "$AREA" <<'PY'
import csv, statistics, sys, pathlib, datetime, os
import numpy as np
from PIL import Image, ImageDraw
from skimage.metrics import peak_signal_noise_ratio as psnr
work, out, repeats, size = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
ref_samples, area = int(sys.argv[5]), sys.argv[6] == "1"
rows = list(csv.reader(open(work / "times.csv")))
def is_run(tag): return tag[:1] == "r" and tag[1:].isdigit()   # timed runs; not "warm" or "ref"
def load(p): return np.asarray(Image.open(p).convert("RGB"))
label = {"fast": "fast AO", "multiray": "multi-ray AO"}
fg_ao = {"fast": "light.fake_ao (1 sample)", "multiray": "light.marched_ao (16 cones)"}
mb_ao = {"fast": "fast AO, quality 4", "multiray": "multi-ray AO, quality 2"}
table, raw = [], []
present = [row for row in ("fast", "multiray") if any(r[1] == row and is_run(r[3]) for r in rows)]
for row in present:
    for s in sorted({int(r[2]) for r in rows if r[1] == row and is_run(r[3])}):
        med = {}
        for tool in ("mandelbulber2", "fractograph"):
            runs = [r for r in rows if r[0] == tool and r[1] == row and int(r[2]) == s and is_run(r[3])]
            wall = statistics.median(float(r[4]) for r in runs)
            cpu = statistics.median(float(r[5]) for r in runs)
            pre = "mb" if tool == "mandelbulber2" else "fg"
            ref = work / f"{pre}-{row}-{ref_samples}-ref.png"
            err = psnr(load(ref), load(work / f"{pre}-{row}-{s}-r1.png"), data_range=255) if ref.exists() else float("nan")
            med[tool] = (wall, cpu, err, len(runs))
            raw += [[tool, row, s, r[3], r[4], r[5]] for r in runs]
        mw, mc, me, n = med["mandelbulber2"]
        fw, fc, fe, _ = med["fractograph"]
        table.append([label[row], s, f"{mw:.1f}", f"{mc:.1f}", ("-" if me != me else f"{me:.1f}"), f"{fw:.1f}", f"{fw / 2:.1f}", f"{fc:.1f}",
                      ("-" if fe != fe else f"{fe:.1f}"), f"{mw / (fw / 2):.1f}", f"{mc / (fc / 2):.1f}", n])
head = ["AO", "samples/pixel", "Mandelbulber2 wall s", "Mandelbulber2 CPU s", "Mandelbulber2 PSNR dB",
        "Fractograph pair wall s", "Fractograph per picture wall s", "Fractograph pair CPU s", "Fractograph PSNR dB",
        "speed-up, wall (per picture)", "speed-up, CPU (per picture)", "runs"]
with open(out / "results.csv", "w", newline="") as f:
    w = csv.writer(f); w.writerow(head); w.writerows(table)
with open(out / "runs.csv", "w", newline="") as f:
    w = csv.writer(f); w.writerow(["tool", "ao", "samples", "run", "wall_s", "cpu_s"]); w.writerows(raw)
md = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)] + ["| " + " | ".join(map(str, r)) + " |" for r in table]
(out / "results.md").write_text(
    f"{size}x{size}, medians of the runs counted in the last column, {os.cpu_count()} CPU cores, {datetime.date.today()}; "
    f"PSNR against the same tool's {ref_samples}-sample picture; Fractograph's soft shadow "
    f"{'an area light (a point of the disc a sample)' if area else 'its cone-angle penumbra in every sample'}.\n\n" + "\n".join(md) + "\n")
print("\n".join(md))
# Side by side: Mandelbulber2 left, Fractograph right, one row per AO method, at 4 samples a pixel
# (or the most there are).
half = 512
shown = {row: max(int(r[2]) for r in rows if r[1] == row and is_run(r[3])) for row in present}
sheet = Image.new("RGB", (2 * half, len(present) * (half + 24)), (255, 255, 255))
d = ImageDraw.Draw(sheet)
for i, row in enumerate(present):
    y = i * (half + 24)
    for j, (pre, name) in enumerate((("mb", f"Mandelbulber2 2.20: {mb_ao[row]}"), ("fg", f"Fractograph: {fg_ao[row]}"))):
        img = Image.open(work / f"{pre}-{row}-{shown[row]}-r1.png").convert("RGB").resize((half, half), Image.LANCZOS)
        sheet.paste(img, (j * half, y + 24))
        d.text((j * half + 6, y + 6), name + f", {shown[row]} sample(s)/pixel", fill=(0, 0, 0))
sheet.save(out / "side_by_side.png", optimize=True)
PY
echo "wrote $OUT/results.md, results.csv, runs.csv and side_by_side.png"
