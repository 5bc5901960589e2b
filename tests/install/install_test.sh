#!/usr/bin/env bash
# The installed form works without the source tree: `cmake --install` into a fresh prefix, and the
# .deb cpack makes (unpacked, not installed), each compile a gallery graph, render it and export
# its surface from an unrelated folder, finding fgc-export beside fgc; the .deb's Depends name
# the libraries the tools link and the Vulkan driver.
#   install_test.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work/elsewhere"
export FG_PASS_CACHE=off FG_PIPELINE_CACHE=off

# Compile, render and export with the tools of PREFIX, run in a folder of their own.
use_tools() {   # PREFIX LABEL
    local prefix=$1 label=$2 run=$work/elsewhere/$2
    mkdir -p "$run"
    (
        cd "$run"
        local graph=$prefix/share/fractograph/graphs/gallery/mandelbulb.json
        [ -f "$graph" ] || { echo "$label: no gallery at $graph"; exit 1; }
        "$prefix/bin/fgc" compile "$graph" -o bulb.fgpack >/dev/null
        "$prefix/bin/fgplay" render bulb.fgpack --out frame --size 64x64 >/dev/null
        "$prefix/bin/fgc" export "$graph" --resolution 24 -o bulb.vdb --mesh bulb.stl --quiet >/dev/null
        for f in bulb.fgpack frame/left.png bulb.vdb bulb.stl; do
            [ -s "$f" ] || { echo "$label: $f was not written"; exit 1; }
        done
        [ -f "$prefix/share/doc/fractograph/formulas.md" ] || { echo "$label: no docs"; exit 1; }
    )
    echo "$label: compiled, rendered and exported from $run"
}

cmake --install "$build" --prefix "$work/prefix" >/dev/null
use_tools "$work/prefix" installed

(cd "$build" && cpack -B "$work/deb" >"$work/cpack.log" 2>&1) || { tail -20 "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/deb/fractograph_*.deb)
dpkg-deb -x "$deb" "$work/unpacked"
use_tools "$work/unpacked/usr" deb
depends=$(dpkg-deb -f "$deb" Depends)
for needed in libvulkan1 libopenxr-loader1 libspirv-cross-c-shared mesa-vulkan-drivers; do
    case "$depends" in
        *"$needed"*) ;;
        *) echo "the .deb's Depends lacks $needed: $depends"; exit 1 ;;
    esac
done
echo "the .deb ($(du -h "$deb" | cut -f1)) depends on: $depends"
