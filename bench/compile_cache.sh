#!/usr/bin/env bash
# What the pass cache on disk saves `fgc compile`, for every gallery graph: compiled with an empty
# cache (cold), again with the cache warm from the same graph, after a one-literal colour edit (the
# `tone` node's scale, which changes the shade and aov passes), and with the cache filled by every
# other gallery graph (passes that depend only on the scene's effects are shared). The cases run
# in turns, so that load on a shared machine hits them alike; medians of RUNS, and a last row with
# the median of the graphs' medians. BEFORE_FGC, an fgc without the cache, compiles cold in the same
# turns.
#   bench/compile_cache.sh FGC [RUNS] [BEFORE_FGC]
# Prints a Markdown table: wall milliseconds of the whole process, and in parentheses the passes
# glslang compiled (the others were read from the cache).
set -euo pipefail
fgc=${1:?usage: compile_cache.sh FGC [RUNS] [BEFORE_FGC]}
runs=${2:-5}
before=${3:-}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
graphs=("$root"/graphs/gallery/*.json)

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# One compile: appends its wall milliseconds to $work/CASE.ms and the passes it compiled to CASE.passes.
timed() {   # CASE FGC CACHE_FOLDER GRAPH
    local start end out
    start=$(date +%s%N)
    out=$(FG_PASS_CACHE="$3" "$2" compile "$4" -o "$work/out.fgpack" -v)
    end=$(date +%s%N)
    echo $(((end - start) / 1000000)) >>"$work/$1.ms"
    sed -n 's/.*cache: *\([0-9]*\) of.*/\1/p' <<<"$out" >>"$work/$1.passes"
}
# The graph with its `tone` node's scale moved by N thousandths: a colour edit.
edited() {   # GRAPH N
    python3 - "$1" "$2" <<'END'
import json, sys
graph = json.load(open(sys.argv[1]))
for node in graph["nodes"]:
    if node["id"] == "tone":
        node["inputs"]["s"] += int(sys.argv[2]) / 1000
print(json.dumps(graph))
END
}
# A graph's median of CASE (kept for the last row), with the passes compiled.
cell() {   # CASE
    median <"$work/$1.ms" | tee -a "$work/$1.medians" | tr -d '\n'
    [[ -s $work/$1.passes ]] && echo " ms ($(median <"$work/$1.passes"))" || echo " ms"
}

header="| graph | cold (empty cache) |"
[[ -n $before ]] && header+=" cold, before the cache |"
echo "$header warm (same graph) | after a one-literal edit | after the rest of the gallery |"
columns=$(($(tr -cd '|' <<<"$header" | wc -c) + 2))
printf '|'; printf -- '---|%.0s' $(seq "$columns"); echo
for ((g = 0; g < ${#graphs[@]}; ++g)); do
    graph=${graphs[g]}
    rm -f "$work"/*.ms "$work"/*.passes
    FG_PASS_CACHE="$work/warm" "$fgc" compile "$graph" -o "$work/out.fgpack" >/dev/null
    for other in "${graphs[@]}"; do
        [[ $other == "$graph" ]] || FG_PASS_CACHE="$work/rest" "$fgc" compile "$other" -o "$work/out.fgpack" >/dev/null
    done
    for ((i = 1; i <= runs; ++i)); do
        rm -rf "$work/cold" "$work/other"
        timed cold "$fgc" "$work/cold" "$graph"
        [[ -n $before ]] && timed before "$before" off "$graph"
        timed warm "$fgc" "$work/warm" "$graph"
        # A value not compiled before, in the cache the unedited graph filled.
        edited "$graph" "$i" >"$work/edited.json"
        timed edit "$fgc" "$work/warm" "$work/edited.json"
        cp -r "$work/rest" "$work/other"
        timed other "$fgc" "$work/other" "$graph"
    done
    row="| $(basename "$graph" .json) | $(cell cold) |"
    [[ -n $before ]] && row+=" $(cell before) |"
    echo "$row $(cell warm) | $(cell edit) | $(cell other) |"
    rm -rf "$work/warm" "$work/rest"
done
row="| median of the graphs | $(median <"$work/cold.medians") ms |"
[[ -n $before ]] && row+=" $(median <"$work/before.medians") ms |"
echo "$row $(median <"$work/warm.medians") ms | $(median <"$work/edit.medians") ms | $(median <"$work/other.medians") ms |"
