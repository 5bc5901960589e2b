#!/usr/bin/env bash
# A governed headset run against the project's test OpenXR runtime behaving as Monado does: no
# XR_FB_display_refresh_rate, a 16 ms placeholder first period, periods stretched to whole display
# periods for a slow frame. The gallery bulb with TAA; prints the governor's changes (and the frame
# each came at) and the frames' wall times (xrBeginFrame to xrEndFrame) after the first 10.
#   bench/governed_headset.sh BUILD [PERIOD_MS] [FRAMES] [SIZE] [fgplay xr options...]
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
env XR_RUNTIME_JSON="$build/tests/xr/fg_xr_test_runtime.json" FG_XR_TEST_REPORT="$work/report.json" \
    FG_XR_TEST_DUMP="$work" FG_XR_TEST_STRETCH=1 FG_XR_TEST_NO_REFRESH_RATE=1 FG_XR_TEST_FIRST_PERIOD_MS=16 \
    FG_XR_TEST_PERIODS="$period" \
    "$build/runtime/fgplay" xr "$work/bulb.fgpack" --frames "$frames" --size "${size}x${size}" --taa "$@" |
    grep -E "^governor: (level|dynamic|at the|ended|[0-9]+ of)|^mean GPU"
python3 - "$work/report.json" "$period" <<'PY'
import json, statistics, sys
times = json.load(open(sys.argv[1]))["frame_ms"][10:]
budget = float(sys.argv[2])
p99 = sorted(times)[int(0.99 * len(times))]
print(f"frames after the first 10: median {statistics.median(times):.1f} ms, p99 {p99:.1f} ms, longest {max(times):.1f} ms "
      f"({max(times) / budget:.2f}x the {budget:g} ms display period)")
PY
