#!/usr/bin/env bash
# Frame time of several graphs side by side: each rendered by fgplay at SIZE per eye, in turns
# (a, b, c, a, b, c, ...) so that load on a shared machine hits all alike. Each run renders FRAMES
# frames and keeps the median GPU frame time of all but the first (lavapipe compiles a pipeline on
# its first dispatch).
#   bench/graph_times.sh BUILD RUNS SIZE FRAMES GRAPH.json [GRAPH.json ...]
# A GRAPH may be FILE.json@jacobian: the formula node of FILE made to carry the running Jacobian.
# Prints a Markdown table: median GPU milliseconds per frame over the runs, and each against the first.
set -euo pipefail
build=${1:?usage: graph_times.sh BUILD RUNS SIZE FRAMES GRAPH.json...}
runs=${2:?} size=${3:?} frames=${4:?}
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export FG_PASS_CACHE=off FG_PIPELINE_CACHE=off

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

n=0
for graph in "$@"; do
    file=${graph%@jacobian}
    if [ "$file" != "$graph" ]; then
        python3 -c 'import json, sys
g = json.load(open(sys.argv[1]))
for node in g["nodes"]:
    if node["type"] == "fractal.formula": node["formula"]["derivative"] = "jacobian"
json.dump(g, open(sys.argv[2], "w"))' "$file" "$work/$n.json"
        file=$work/$n.json
    fi
    "$build/compiler/fgc" compile "$file" -o "$work/$n.fgpack" >/dev/null
    n=$((n + 1))
done

for ((run = 1; run <= runs; run++)); do
    for ((k = 0; k < n; k++)); do
        "$build/runtime/fgplay" render "$work/$k.fgpack" --out "$work/out" --size "${size}x${size}" --frames "$frames" 2>&1 |
            sed -n 's/^frame \([0-9]*\):.*GPU frame \([0-9.]*\) ms.*/\1 \2/p' | awk '$1 > 0 {print $2}' | median >>"$work/$k.ms"
    done
    printf '\r  run %d of %d' "$run" "$runs" >&2
done
printf '\n' >&2

echo "| graph, ${size}² per eye | ms | against the first |"
echo "|---|---:|---:|"
first=$(median <"$work/0.ms")
k=0
for graph in "$@"; do
    ms=$(median <"$work/$k.ms")
    awk -v g="$(basename "$graph")" -v a="$ms" -v f="$first" 'BEGIN { printf "| %s | %.1f | %.2f |\n", g, a, a / f }'
    k=$((k + 1))
done
