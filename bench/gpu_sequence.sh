#!/usr/bin/env bash
# The benchmarks on a lent GPU machine, inside a fixed budget of seconds. Here, first:
#   bash ../shared/tools/gpu-bundle.sh build/gpu build/runtime/fgplay && strip build/gpu/fgplay
#   tar cJf build/gpu.tar.xz -C build gpu
# (the bundle, 28 MB, beside the tracked tree, 43 MB, would overflow the device's 64 MiB; xz makes it 8 MB)
# then on the device, from the repository root, with build/gpu.tar.xz carried:
#   bash bench/gpu_sequence.sh "$OUT" SECONDS RUN...
# where each RUN is one of
#   NAME:SIZE:SCENE[:TRACE,...[:N[:VARIANT/...]]]
#                                        head traces (fgplay bench --sequence) over graphs/gallery/SCENE.json,
#                                        errors on one frame in N (--compare-every N; default every frame), and
#                                        per-eye again with each VARIANT's knobs (--variant knob=value[,knob=value]),
#                                        e.g. bulb1920:1920:mandelbulb:look_around:6:cone_steps=16
#   frame:NAME:SIZE:SCENE[:VIEW,...]     single frames of every setting (fgplay bench), e.g. the filled
#                                        view at a headset's size: frame:bulb1920:1920:mandelbulb:filled
# Each run's folder comes back as NAME.tar.gz (plots are drawn here afterwards: the GPU machine's
# Python may lack matplotlib); log.txt says what ran, how long, and which runs the budget cut.
# Without build/gpu (a machine with its own Vulkan) it runs the fgplay on PATH.
set -u
out=$1 budget=$2
shift 2
log=$out/log.txt
if [ ! -d build/gpu ] && [ -f build/gpu.tar.xz ]; then
    tar xJf build/gpu.tar.xz -C build ||
        python3 -c 'import tarfile; tarfile.open("build/gpu.tar.xz").extractall("build")'
fi
[ -f build/gpu/gpu-env.sh ] && source build/gpu/gpu-env.sh build/gpu
{
    date -u
    nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,temperature.gpu --format=csv 2>&1
} >>"$log"
for run in "$@"; do
    kind=sequence
    if [[ $run == frame:* ]]; then kind=frame run=${run#frame:}; fi
    IFS=: read -r name size scene subset compare_every variants <<<"$run"
    left=$((budget - SECONDS))
    if ((left < 20)); then
        echo "$name: not run, $left s of the budget left" | tee -a "$log"
        continue
    fi
    if [ "$kind" = sequence ]; then
        args=(bench --sequence --no-plots --size "$size" --scene "graphs/gallery/$scene.json" --out "/tmp/$name")
        [ -n "$subset" ] && args+=(--trace ${subset//,/ })
        [ -n "$compare_every" ] && args+=(--compare-every "$compare_every")
        for variant in ${variants//\// }; do args+=(--variant "$variant"); done
    else
        args=(bench --graph "graphs/gallery/$scene.json" --no-plots --size "$size" --out "/tmp/$name")
        for view in ${subset//,/ }; do args+=(--view "$view"); done
    fi
    began=$SECONDS
    timeout "$left" fgplay "${args[@]}" >"/tmp/$name.log" 2>&1
    rc=$?
    echo "$name: fgplay ${args[*]}: exit $rc after $((SECONDS - began)) s" | tee -a "$log"
    cp "/tmp/$name.log" "/tmp/$name/" 2>/dev/null || { mkdir -p "/tmp/$name" && cp "/tmp/$name.log" "/tmp/$name/"; }
    tar czf "$out/$name.tar.gz" -C /tmp "$name"
    # A file over 16 MiB does not come back from the device: at a headset's size the sweep's
    # images would sink its CSV (the Mandelbox's reference alone is 21 MB at 1920²), so drop
    # the settings' images, then the reference's.
    for keep in "reference_*" "no image"; do
        (($(stat -c %s "$out/$name.tar.gz") > 15000000)) || break
        find "/tmp/$name" -name '*.png' ! -name "$keep" -delete
        tar czf "$out/$name.tar.gz" -C /tmp "$name"
        echo "$name: archived without its images but $keep (too large to come back)" | tee -a "$log"
    done
    tail -n 4 "/tmp/$name.log"
done
