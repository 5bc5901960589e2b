#!/usr/bin/env bash
# A governed headset run of the gallery bulb (add --taa and any other fgplay xr option); prints the governor's changes (and the frame
# each came at) and fgplay's frame times (xrBeginFrame to xrEndFrame) after the first 10.
#   bench/governed_headset.sh BUILD [PERIOD_MS] [FRAMES] [SIZE] [fgplay xr options...]
# Against the project's test OpenXR runtime behaving as Monado does (no XR_FB_display_refresh_rate, a
# 16 ms placeholder first period, periods stretched to whole display periods for a slow frame), or
# against Monado itself with MONADO_JSON=its openxr_monado-dev.json (bench/monado/build.sh; its null
# compositor's display is 20 Hz whatever PERIOD_MS says).
set -euo pipefail
build=$(cd "${1:?usage: governed_headset.sh BUILD [PERIOD_MS] [FRAMES] [SIZE] [options...]}" && pwd)
period=${2:-20}
frames=${3:-600}
size=${4:-256}
shift $(($# < 4 ? $# : 4))
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/compiler/fgc" compile "$root/graphs/gallery/mandelbulb.json" -o "$work/bulb.fgpack" >/dev/null
if [ -n "${MONADO_JSON:-}" ]; then
  runtime=(XR_RUNTIME_JSON="$MONADO_JSON" XRT_COMPOSITOR_NULL=1)
else
  runtime=(XR_RUNTIME_JSON="$build/tests/xr/fg_xr_test_runtime.json" FG_XR_TEST_DUMP="$work" FG_XR_TEST_STRETCH=1
           FG_XR_TEST_NO_REFRESH_RATE=1 FG_XR_TEST_FIRST_PERIOD_MS=16 FG_XR_TEST_PERIODS="$period")
fi
env "${runtime[@]}" "$build/runtime/fgplay" xr "$work/bulb.fgpack" --frames "$frames" --size "${size}x${size}" "$@" |
  grep -E "^governor: (budget|level|dynamic|at the|ended|[0-9]+ of)|^mean GPU|^frame times"
