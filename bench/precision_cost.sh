#!/usr/bin/env bash
# What precision "double" costs on this device: the same view compiled in float and in double,
# rendered in turns (so load on a shared machine hits both alike), median of N frames each.
#   bench/precision_cost.sh BUILD_DIR [SIZE] [FRAMES]
# Views: graphs/hard/deep_zoom.json (float is wrong there: its evaluation count is noise) and the
# gallery bulb from its scene camera (float is right there: the same evaluations, so the time
# ratio is the price of double itself). Prints a Markdown table.
set -euo pipefail
build=${1:?usage: precision_cost.sh BUILD_DIR [SIZE] [FRAMES]}
size=${2:-96}
frames=${3:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DIR="$work/mesa"

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "| view | stereo | precision | SDF evaluations / px | march ms | frame ms | frame ms / evaluation per px |"
echo "|---|---|---|---|---|---|---|"
for graph in graphs/hard/deep_zoom.json graphs/gallery/mandelbulb.json; do
    name=$(basename "$graph" .json)
    for precision in float double; do
        "$build/compiler/fgc" compile "$root/$graph" --precision "$precision" -o "$work/$name.$precision.fgpack" >/dev/null
    done
    for stereo in per-eye naive; do
        for precision in float double; do : >"$work/$name.$stereo.$precision.log"; done
        for ((i = 0; i < frames; ++i)); do
            for precision in float double; do
                "$build/runtime/fgplay" render "$work/$name.$precision.fgpack" --out "$work/out" --size "${size}x${size}" \
                    --stereo "$stereo" >>"$work/$name.$stereo.$precision.log" 2>&1
            done
        done
        for precision in float double; do
            log="$work/$name.$stereo.$precision.log"
            evals=$(grep -o 'per output pixel: [0-9.]*' "$log" | head -1 | awk '{print $4}')
            march=$(grep -o 'march [0-9.]* ms' "$log" | awk '{print $2}' | median)
            frame=$(grep -o 'GPU frame [0-9.]* ms' "$log" | awk '{print $3}' | median)
            per=$(awk -v f="$frame" -v e="$evals" 'BEGIN {printf "%.2f", f / e}')
            echo "| $name | $stereo | $precision | $evals | $march | $frame | $per |"
        done
    done
done
