#!/usr/bin/env bash
# Builds Monado's in-process OpenXR runtime (the openxr_monado target) from a Monado source tree, for
# checks by hand against a real runtime: the null compositor (XRT_COMPOSITOR_NULL=1, a 20 Hz display)
# and the simulated HMD (320x240 per eye) need no headset and no display.
#   bench/monado/build.sh MONADO_SOURCE [BUILD_DIR]   (source: git clone https://gitlab.freedesktop.org/monado/monado)
# Prints the runtime manifest to point XR_RUNTIME_JSON at. About 3 minutes on 2 cores.
set -euo pipefail
src=$(cd "${1:?usage: build.sh MONADO_SOURCE [BUILD_DIR]}" && pwd)
build=${2:-$src/build}
# What Monado's CMakeLists requires beyond Fractograph's own packages (scripts/fractograph.sh packages test).
packages=(libeigen3-dev libudev-dev libx11-xcb-dev libxrandr-dev libxcb-randr0-dev python3)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=(); [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# In-process (no monado-service), no tracking stacks or GUI: only what the null compositor run needs.
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DXRT_FEATURE_SERVICE=OFF \
  -DXRT_FEATURE_COMPOSITOR_NULL=ON -DXRT_HAVE_SDL2=OFF -DXRT_FEATURE_STEAMVR_PLUGIN=OFF \
  -DXRT_FEATURE_TRACING=OFF -DBUILD_TESTING=OFF >"$build.configure.log"
cmake --build "$build" --target openxr_monado -j "$(nproc)" >"$build.build.log"
find "$build" -name 'openxr_monado-dev.json' -print -quit
