#!/usr/bin/env bash
# What the offline look costs on a lent GPU: each lit example's single frame, pass by pass, and its
# samples, at one size. Here, first, bundle both programs (packs are compiled there, since the
# environment images make two of them 5 MB each):
#   bash ../shared/tools/gpu-bundle.sh build/gpu build/runtime/fgplay build/compiler/fgc &&
#     strip build/gpu/fgplay build/gpu/fgc && tar cJf build/gpu.tar.xz -C build gpu
# then on the device, from the repository root, with build/gpu.tar.xz carried:
#   bash bench/gpu_offline_look.sh "$OUT" SECONDS WxH SAMPLES [NAME:N,N... (more sample counts for one example)]
# Without build/gpu (a machine with its own Vulkan) it runs the fgc and fgplay on PATH.
# OUT gets log.txt (what ran, how long), renders.txt (fgplay's own report of every run) and
# clocks.csv (the shader clock every 250 ms: GPU times mean something only at a known clock).
set -u
out=$1 budget=$2 size=$3 samples=$4
shift 4
if [ ! -d build/gpu ] && [ -f build/gpu.tar.xz ]; then
    tar xJf build/gpu.tar.xz -C build
fi
[ -f build/gpu/gpu-env.sh ] && source build/gpu/gpu-env.sh build/gpu
log=$out/log.txt renders=$out/renders.txt
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv >>"$log" 2>&1
nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv -lms 250 \
    >"$out/clocks.csv" 2>/dev/null &
clocks=$!
graphs=(gallery/mandelbulb examples/lit_mandelbulb gallery/mandelbox_halls gallery/halls_shafts
    gallery/hdri_mandelbulb gallery/glass_ball)
declare -A extra
for more in "$@"; do extra[${more%%:*}]=${more#*:}; done

# Runs fgplay with what is left of the budget; its report goes to renders.txt under a heading.
render() {
    local title=$1 left=$((budget - SECONDS)) began=$SECONDS
    shift
    if ((left < 10)); then
        echo "$title: not run, $left s of the budget left" | tee -a "$log"
        return
    fi
    echo "## $title: fgplay render $*" >>"$renders"
    timeout "$left" fgplay render "$@" --out /tmp/offline_look --no-progress >>"$renders" 2>&1
    echo "$title: exit $? after $((SECONDS - began)) s" | tee -a "$log"
}

mkdir -p /tmp/offline_packs
for graph in "${graphs[@]}"; do
    name=${graph#*/}
    pack=/tmp/offline_packs/$name.fgpack
    fgc compile "graphs/$graph.json" -o "$pack" >/dev/null || { echo "$name: fgc failed" | tee -a "$log"; continue; }
    # Three frames after fgplay's untimed warm-up. Each process starts at the full clock, which falls
    # while the PNGs are written: clocks.csv says which frames ran at it.
    render "$name frame" "$pack" --size "$size" --time-passes --frames 3
    render "$name $samples samples" "$pack" --size "$size" --samples "$samples"
done
# The further sample counts last, so a short budget cuts them rather than an example.
for name in "${!extra[@]}"; do
    more=${extra[$name]}
    for n in ${more//,/ }; do
        render "$name $n samples" "/tmp/offline_packs/$name.fgpack" --size "$size" --samples "$n"
    done
done
kill "$clocks" 2>/dev/null
