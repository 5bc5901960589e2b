#!/usr/bin/env bash
# fgplay view --watch: saving a broken graph shows a compile error and the old pack keeps playing;
# saving a good graph swaps the new pack in.
set -u
XVFB_RUN=$1 FGPLAY=$2 GRAPH=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK"
cp "$GRAPH" "$WORK/graph.json"
export MESA_SHADER_CACHE_DIR=$WORK/mesa_cache
"$XVFB_RUN" -a -s "-screen 0 320x240x24" bash -c \
  "'$FGPLAY' view '$WORK/graph.json' --watch --frames 100000 --size 48x48 > '$WORK/log' 2>&1 & echo \$! > '$WORK/pid'; wait" &
runner=$!
for _ in $(seq 100); do [ -s "$WORK/pid" ] && break; sleep 0.1; done
pid=$(cat "$WORK/pid")
# A passing test removes its folder (FG_KEEP_TEST_FILES=1 keeps it); a failing one leaves it to look at.
finish() {
  kill "$pid" 2>/dev/null; wait "$runner" 2>/dev/null; cat "$WORK/log"
  [ "$1" -eq 0 ] && [ "${FG_KEEP_TEST_FILES:-}" != 1 ] && rm -rf "$WORK"
  exit "$1"
}
wait_for() {
  for _ in $(seq 1200); do
    grep -q "$1" "$WORK/log" && return 0
    kill -0 "$pid" 2>/dev/null || { echo "fgplay view exited while waiting for: $1"; finish 1; }
    sleep 0.1
  done
  echo "timed out waiting for: $1"; finish 1
}
wait_for "^frame 1:"
sleep 0.3   # a later modification time than the first load
echo '{"format": "fractograph-graph", "version": 1, "nodes": [' > "$WORK/graph.json"
wait_for "compile error (the previous pack keeps playing)"
sleep 0.3
sed 's/"name": "Mandelbulb"/"name": "Mandelbulb, edited"/' "$GRAPH" > "$WORK/graph.json"
wait_for "reloaded Mandelbulb, edited in"
# Still rendering after the swap: the frame counter in the log moves on.
kill -0 "$pid" 2>/dev/null || { echo "fgplay view died after the reload"; finish 1; }
finish 0
