#!/usr/bin/env bash
# Adaptive against uniform sampling at equal time, on two depth-of-field scenes: the gallery's bulb
# close up (fractal in every pixel) and the lit bulb of docs/shading.md (a third of it background).
# Each rendered with N uniform samples and with noise targets (at most 128 samples a pixel); each
# picture's PSNR against a 1024-sample reference (whose lens points the others share only as a
# short prefix), its samples a pixel and its GPU time (lavapipe: the sum over its samples, both eyes).
#   bash bench/adaptive_sampling.sh [WxH] [OUT]     (default 240x135, docs/bench/adaptive_sampling)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FG_BUILD_DIR:-$ROOT/build}
SIZE=${1:-240x135}
OUT=${2:-$ROOT/docs/bench/adaptive_sampling}
FGC=${FGC:-$BUILD/compiler/fgc}
FGPLAY=${FGPLAY:-$BUILD/runtime/fgplay}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$BUILD/mesa-cache}
mkdir -p "$OUT"

# GPU milliseconds of the frame (every sample) from fgplay's report.
render() {
  local name=$1; shift
  "$FGPLAY" render "$WORK/$SCENE.fgpack" --out "$WORK/$name" --size "$SIZE" $LENS --no-progress "$@" >"$WORK/$name.log"
  grep -o 'GPU frame [0-9.]* ms' "$WORK/$name.log" | grep -o '[0-9.]*'
}

echo "scene,sampling,max_samples,noise_target,mean_samples,gpu_ms,psnr_db" >"$OUT/results.csv"
measure() {
  local kind=$1 samples=$2 noise=$3; shift 3
  local name="$SCENE-$kind-$samples-$noise" ms mean psnr
  ms=$(render "$name" --samples "$samples" "$@")
  mean=$(grep -o '[0-9.]* samples a pixel' "$WORK/$name.log" | grep -o '^[0-9.]*' || echo "$samples")
  psnr=$(/usr/bin/python3 - "$WORK/$SCENE-reference/left.png" "$WORK/$name/left.png" <<'PY'
import sys
from skimage.io import imread
from skimage.metrics import peak_signal_noise_ratio
a, b = imread(sys.argv[1])[..., :3], imread(sys.argv[2])[..., :3]
print(f"{peak_signal_noise_ratio(a, b, data_range=255):.2f}")
PY
)
  echo "$SCENE,$kind,$samples,$noise,$mean,$ms,$psnr" | tee -a "$OUT/results.csv"
}
# name, graph, lens and camera
while read -r SCENE graph LENS; do
  "$FGC" compile "$ROOT/$graph" -o "$WORK/$SCENE.fgpack" >/dev/null
  echo "==> $SCENE: reference, 1024 samples"
  render "$SCENE-reference" --samples 1024 >/dev/null
  cp "$WORK/$SCENE-reference/left.png" "$OUT/$SCENE.png"
  for n in 16 32 64 128; do measure uniform "$n" 0; done
  for t in 0.03 0.02 0.01; do measure adaptive 128 "$t" --noise "$t" --min-samples 16; done
done <<'SCENES'
gallery_bulb graphs/gallery/mandelbulb_dof.json --aperture 0.1 --focus 1.2
lit_bulb graphs/examples/lit_mandelbulb.json --aperture 0.08 --camera 0.9,0.35,1.3,0.2,0.0,0.0
SCENES
echo "results in $OUT/results.csv"
