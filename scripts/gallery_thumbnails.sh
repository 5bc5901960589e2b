#!/usr/bin/env bash
# Renders a thumbnail of every gallery scene (graphs/gallery/*.json) into docs/images/gallery/ and
# rewrites docs/gallery.md from the graphs' names and descriptions. Headless, on lavapipe without a GPU.
#   bash scripts/gallery_thumbnails.sh [size] [--full | --page]
#     size     thumbnail size, default 256 (one eye, size x size)
#     --page   only rewrite docs/gallery.md from the pictures already there
#     --full   also render the full-size offline pictures listed in OFFLINE below (minutes each),
#              timing each render; without it the page reuses the pictures and times already in
#              docs/images/gallery/ (NAME_full.png and NAME_full.time)
#     NAME     with --full: only these scenes' full-size pictures (repeatable)
# Tools: $FG_BUILD_DIR/compiler/fgc and $FG_BUILD_DIR/runtime/fgplay (FG_BUILD_DIR defaults to build/),
# or FGC=... FGPLAY=... to name them directly.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FG_BUILD_DIR:-$ROOT/build}
SIZE=256
FULL=0
PAGE_ONLY=0
ONLY=" "
for arg in "$@"; do
  case "$arg" in
    --full) FULL=1 ;;
    --page) PAGE_ONLY=1 ;;
    [0-9]*) SIZE=$arg ;;
    *) ONLY+="$arg " ;;
  esac
done
FGC=${FGC:-$BUILD/compiler/fgc}
FGPLAY=${FGPLAY:-$BUILD/runtime/fgplay}
IMAGES=$ROOT/docs/images/gallery
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$BUILD/mesa-cache}

# Offline renders: scenes made for stills (marched shadows, AO, reflections, depth of field) get a
# full-size picture on the page beside their thumbnail, with the fgplay render options below.
# One line per scene: NAME <tab-free spaces> OPTIONS.
OFFLINE='
mandelbox_halls --size 960x540 --samples 9
mandelbulb_dof --size 960x540 --samples 64 --aperture 0.1 --focus 1.2
hdri_mandelbulb --size 960x540 --samples 16
halls_shafts --size 960x540 --samples 16
glass_ball --size 960x540 --samples 16
'

mkdir -p "$IMAGES"
if [ "$PAGE_ONLY" = 0 ]; then
for tool in "$FGC" "$FGPLAY"; do
  [ -x "$tool" ] || { echo "missing $tool: build first (bash scripts/fractograph.sh build)"; exit 1; }
done

for graph in "$ROOT"/graphs/gallery/*.json; do
  name=$(basename "$graph" .json)
  echo "==> $name"
  "$FGC" compile "$graph" -o "$WORK/$name.fgpack" >/dev/null
  "$FGPLAY" render "$WORK/$name.fgpack" --out "$WORK/$name" --size "${SIZE}x${SIZE}" >/dev/null
  cp "$WORK/$name/left.png" "$IMAGES/$name.png"
done

if [ "$FULL" = 1 ]; then
  while read -r name options; do
    [ -n "$name" ] || continue
    [ "$ONLY" = " " ] || [[ $ONLY == *" $name "* ]] || continue
    echo "==> $name, full size: fgplay render $name.fgpack $options"
    # Wall time of the whole command (both eyes: fgplay render always renders a stereo pair) and
    # the CPU time it used; the left eye is the picture.
    /usr/bin/time -o "$WORK/$name.time" -f '%e %U %S' \
      "$FGPLAY" render "$WORK/$name.fgpack" --out "$WORK/$name-full" $options >/dev/null
    cp "$WORK/$name-full/left.png" "$IMAGES/${name}_full.png"
    read -r wall user sys <"$WORK/$name.time"
    # wall s, CPU s, cores, date, the 5-minute load average at the end (other jobs stretch the wall time)
    printf '%s %s %s %s %s\n' "$wall" "$(echo "$user + $sys" | bc)" "$(nproc)" "$(date -u +%Y-%m-%d)" \
      "$(cut -d' ' -f2 /proc/loadavg)" >"$IMAGES/${name}_full.time"
  done <<<"$OFFLINE"
fi
fi

# The page: one section per scene, in file order, from the graph's own name and description.
OFFLINE="$OFFLINE" /usr/bin/python3 - "$ROOT" <<'PY'
import json, os, pathlib, sys
root = pathlib.Path(sys.argv[1])
offline = dict(line.split(None, 1) for line in os.environ["OFFLINE"].strip().splitlines())
out = ["# The gallery", "",
       "Scenes in `graphs/gallery/`, each a graph you can compile and fly through:",
       "`fgc compile graphs/gallery/NAME.json -o NAME.fgpack`, then `fgplay view NAME.fgpack` or `fgplay xr NAME.fgpack`.",
       "The thumbnails are the left eye of the scene's start view, rendered headless on lavapipe by",
       "`scripts/gallery_thumbnails.sh` (do not edit this page by hand: that script writes it).",
       "Every scene is also rendered by the test suite (`tests/runtime/gallery_test.cpp`) and checked against the CPU twin.",
       "Scenes lit for stills also show a full-size offline render, with the command that made it and what it took",
       "(`scripts/gallery_thumbnails.sh --full` renders them again; an H200 renders each in well under a second",
       "of GPU time: [shading.md](shading.md#what-the-lit-examples-cost-on-a-gpu)).", ""]
graphs = [(path, json.loads(path.read_text())) for path in sorted((root / "graphs" / "gallery").glob("*.json"))]
# A grid of thumbnails first (users look rather than read), then what each scene is made of.
columns = 4
for i in range(0, len(graphs), columns):
    row = graphs[i:i + columns]
    cells = [f"[![{g['name']}](images/gallery/{p.stem}.png)](#{p.stem})<br>{g['name']}" for p, g in row]
    cells += [""] * (columns - len(row))
    if i == 0:
        out += ["| " + " | ".join([""] * columns) + " |", "|" + "---|" * columns]
    out.append("| " + " | ".join(cells) + " |")
out.append("")
for path, g in graphs:
    types = sorted({n["type"] for n in g["nodes"] if n["type"].startswith(("fractal.", "prim.", "op."))})
    lights = sorted({n["type"] for n in g["nodes"] if n["type"] in
                     ("light.soft_shadow", "light.marched_ao", "light.specular", "light.reflection",
                      "light.refraction")})
    scene = g.get("scene", {})
    extras = [k for k in ("environment", "fog", "glow", "vignette") if k in scene]
    out += [f'<a id="{path.stem}"></a>', "", f"## {g['name']}", "",
            g.get("description", ""), "",
            f"`graphs/gallery/{path.name}` · nodes: {', '.join('`%s`' % t for t in types)}"
            + (f" · marched light: {', '.join('`%s`' % t for t in lights)}" if lights else "")
            + (f" · effects: {', '.join(extras)}" if extras else " · no fog or glow"), ""]
    stem = path.stem
    picture = root / "docs" / "images" / "gallery" / f"{stem}_full.png"
    timing = root / "docs" / "images" / "gallery" / f"{stem}_full.time"
    if stem in offline and picture.exists() and timing.exists():
        wall, cpu, cores, day, *load = timing.read_text().split()
        out += [f"![{g['name']}, full size](images/gallery/{stem}_full.png)", "",
                "```",
                f"fgc compile graphs/gallery/{path.name} -o {stem}.fgpack",
                f"fgplay render {stem}.fgpack --out {stem} {offline[stem].strip()}",
                "```", "",
                f"{float(wall):.0f} s for the stereo pair (`fgplay render` renders both eyes; the picture is the left one), "
                f"{float(cpu):.0f} s of CPU time, on lavapipe with {cores} CPU cores ({day}"
                + (f"; the machine ran other jobs too, 5-minute load average {float(load[0]):.1f}, so the wall time is"
                   f" longer than the CPU time over {cores} cores" if load and float(load[0]) > float(cores) else "") + ").", ""]
(root / "docs" / "gallery.md").write_text("\n".join(out))
PY
echo "wrote docs/gallery.md and $(ls "$IMAGES" | wc -l) files in docs/images/gallery/"
