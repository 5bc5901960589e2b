#!/usr/bin/env bash
# The sequence benchmark on a lent GPU machine, inside a fixed budget of seconds. Here, first:
#   bash ../shared/tools/gpu-bundle.sh build/gpu build/runtime/fgplay && strip build/gpu/fgplay
# then on the device, from the repository root, with build/gpu carried:
#   bash bench/gpu_sequence.sh "$OUT" SECONDS [NAME:SIZE:SCENE[:TRACE,...]]...
# Each run's folder comes back as NAME.tar.gz (plots are drawn here afterwards: the GPU machine's
# Python may lack matplotlib); log.txt says what ran, how long, and which runs the budget cut.
set -u
out=$1 budget=$2
shift 2
log=$out/log.txt
source build/gpu/gpu-env.sh build/gpu
{
    date -u
    nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,temperature.gpu --format=csv 2>&1
} >>"$log"
for run in "$@"; do
    IFS=: read -r name size scene traces <<<"$run"
    left=$((budget - SECONDS))
    if ((left < 20)); then
        echo "$name: not run, $left s of the budget left" | tee -a "$log"
        continue
    fi
    args=(bench --sequence --no-plots --size "$size" --scene "graphs/gallery/$scene.json" --out "/tmp/$name")
    [ -n "$traces" ] && args+=(--trace ${traces//,/ })
    began=$SECONDS
    timeout "$left" fgplay "${args[@]}" >"/tmp/$name.log" 2>&1
    rc=$?
    echo "$name: fgplay ${args[*]}: exit $rc after $((SECONDS - began)) s" | tee -a "$log"
    cp "/tmp/$name.log" "/tmp/$name/" 2>/dev/null || { mkdir -p "/tmp/$name" && cp "/tmp/$name.log" "/tmp/$name/"; }
    tar czf "$out/$name.tar.gz" -C /tmp "$name"
    tail -n 4 "/tmp/$name.log"
done
