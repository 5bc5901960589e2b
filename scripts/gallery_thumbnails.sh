#!/usr/bin/env bash
# Renders a thumbnail of every gallery scene (graphs/gallery/*.json) into docs/images/gallery/ and
# rewrites docs/gallery.md from the graphs' names and descriptions. Headless, on lavapipe without a GPU.
#   bash scripts/gallery_thumbnails.sh [size]      (default 256: one eye, size x size)
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FG_BUILD_DIR:-$ROOT/build}
SIZE=${1:-256}
FGC=$BUILD/compiler/fgc
FGPLAY=$BUILD/runtime/fgplay
IMAGES=$ROOT/docs/images/gallery
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$BUILD/mesa-cache}

for tool in "$FGC" "$FGPLAY"; do
  [ -x "$tool" ] || { echo "missing $tool: build first (bash scripts/fractograph.sh build)"; exit 1; }
done
mkdir -p "$IMAGES"

for graph in "$ROOT"/graphs/gallery/*.json; do
  name=$(basename "$graph" .json)
  echo "==> $name"
  "$FGC" compile "$graph" -o "$WORK/$name.fgpack" >/dev/null
  "$FGPLAY" render "$WORK/$name.fgpack" --out "$WORK/$name" --size "${SIZE}x${SIZE}" >/dev/null
  cp "$WORK/$name/left.png" "$IMAGES/$name.png"
done

# The page: one section per scene, in file order, from the graph's own name and description.
/usr/bin/python3 - "$ROOT" <<'PY'
import json, pathlib, sys
root = pathlib.Path(sys.argv[1])
out = ["# The gallery", "",
       "Scenes in `graphs/gallery/`, each a graph you can compile and fly through:",
       "`fgc compile graphs/gallery/NAME.json -o NAME.fgpack`, then `fgplay view NAME.fgpack` or `fgplay xr NAME.fgpack`.",
       "The thumbnails are the left eye of the scene's start view, rendered headless on lavapipe by",
       "`scripts/gallery_thumbnails.sh` (do not edit this page by hand: that script writes it).",
       "Every scene is also rendered by the test suite (`tests/runtime/gallery_test.cpp`) and checked against the CPU twin.", ""]
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
    scene = g.get("scene", {})
    extras = [k for k in ("fog", "glow", "vignette") if k in scene]
    out += [f'<a id="{path.stem}"></a>', "", f"## {g['name']}", "",
            g.get("description", ""), "",
            f"`graphs/gallery/{path.name}` · nodes: {', '.join('`%s`' % t for t in types)}"
            + (f" · effects: {', '.join(extras)}" if extras else " · no fog or glow"), ""]
(root / "docs" / "gallery.md").write_text("\n".join(out))
PY
echo "wrote docs/gallery.md and $(ls "$IMAGES" | wc -l) images in docs/images/gallery/"
