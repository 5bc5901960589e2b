#!/usr/bin/env bash
# What a formula graph costs against the hand-written fractal node it redraws: five gallery scenes
# (graphs/gallery/) and their formula graphs (graphs/formulas/), each
# rendered by fgplay at SIZE per eye, in turns (node, formula, node, formula, ...) so that load on a
# shared machine hits both alike. Each run renders FRAMES frames and keeps the median GPU frame
# time of all but the first (lavapipe compiles a pipeline on its first dispatch).
#   bench/formula_graphs.sh BUILD [RUNS] [SIZE] [FRAMES]
# Prints a Markdown table: median GPU milliseconds per frame over the runs, and formula / node.
set -euo pipefail
build=${1:?usage: formula_graphs.sh BUILD [RUNS] [SIZE] [FRAMES]}
runs=${2:-5}
size=${3:-256}
frames=${4:-6}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export FG_PASS_CACHE=off FG_PIPELINE_CACHE=off
names="mandelbox mandelbulb menger_twisted kleinian julia"

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

for name in $names; do
    for kind in gallery formulas; do
        "$build/compiler/fgc" compile "$root/graphs/$kind/$name.json" -o "$work/$kind-$name.fgpack" >/dev/null
    done
done

for ((run = 1; run <= runs; run++)); do
    for name in $names; do
        for kind in gallery formulas; do
            "$build/runtime/fgplay" render "$work/$kind-$name.fgpack" --out "$work/out" --size "${size}x${size}" \
                --frames "$frames" 2>&1 | sed -n 's/^frame \([0-9]*\):.*GPU frame \([0-9.]*\) ms.*/\1 \2/p' |
                awk '$1 > 0 {print $2}' | median >>"$work/$kind-$name.ms"
        done
    done
    printf '\r  run %d of %d' "$run" "$runs" >&2
done
printf '\n' >&2

if [ -n "${FG_BENCH_VERBOSE:-}" ]; then
    for f in "$work"/*.ms; do echo "$(basename "$f"): $(tr '\n' ' ' <"$f")" >&2; done
fi
echo "| fractal, ${size}² per eye | node ms | formula graph ms | formula / node |"
echo "|---|---:|---:|---:|"
for name in $names; do
    node=$(median <"$work/gallery-$name.ms")
    formula=$(median <"$work/formulas-$name.ms")
    awk -v n="$name" -v a="$node" -v b="$formula" 'BEGIN { printf "| %s | %.1f | %.1f | %.3f |\n", n, a, b, b / a }'
done
