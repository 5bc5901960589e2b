#!/usr/bin/env bash
# CPU instructions per frame on lavapipe, counted by valgrind (cachegrind): exact and repeatable on
# a shared machine, where lavapipe's milliseconds move by tens of percent from run to run. llvmpipe
# runs every shader on the CPU, so its instructions are the frame's work. Each setting renders 1 and
# 3 frames of the filled view of the gallery bulb (or GRAPH and CAMERA); the difference over 2 is
# one frame without pipeline compilation. Slow (about a minute per row at 96x96): a benchmark, not
# a test. Needs valgrind (apt-get install valgrind).
#   bench/cpu_instructions.sh BUILD_DIR [SIZE] [GRAPH] [CAMERA px,py,pz,tx,ty,tz]
set -euo pipefail
build=${1:?usage: cpu_instructions.sh BUILD_DIR [SIZE] [GRAPH] [CAMERA]}
size=${2:-96}
root=$(cd "$(dirname "$0")/.." && pwd)
graph=${3:-$root/graphs/gallery/mandelbulb.json}
camera=${4:-0,0.55,1.45,0,0,0}
command -v valgrind >/dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/compiler/fgc" compile "$graph" -o "$work/pack.fgpack" >/dev/null

instructions() {   # frames, then fgplay render options
    local frames=$1; shift
    MESA_SHADER_CACHE_DISABLE=true LP_NUM_THREADS=0 valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
        "$build/runtime/fgplay" render "$work/pack.fgpack" --size "${size}x${size}" --out "$work/out" --camera "$camera" \
        --frames "$frames" "$@" 2>&1 | sed -n 's/.*I *refs: *//p' | tr -d ,
}

echo "| setting | million instructions per frame |"
echo "|---|---|"
for setting in "per-eye:--stereo per-eye" "per-eye, persistent lanes:--stereo per-eye --knob persistent_lanes=1" \
               "naive:--stereo naive" "naive, persistent lanes:--stereo naive --knob persistent_lanes=1"; do
    name=${setting%%:*}
    read -r -a options <<< "${setting#*:}"
    one=$(instructions 1 "${options[@]}")
    three=$(instructions 3 "${options[@]}")
    echo "| $name | $(( (three - one) / 2 / 1000000 )) |"
done
