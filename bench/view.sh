#!/usr/bin/env bash
# Frame time of the desktop viewer under Xvfb (Mesa through GLX, llvmpipe without a GPU): a
# scripted orbit of FRAMES steps (360 degrees around, as `render --orbit FRAMES`), no panel, and
# the median draw time `voltree view` prints (traversal, upload, draw, glFinish; no swap). A step
# every half second: a script applies every event whose time has come before the next frame, so
# steps closer than a frame would be drawn together.
# Usage: bench/view.sh INPUT [SIZE=512x512] [FRAMES=36] [VOLTREE=build/voltree] [VIEW OPTIONS...]
#   e.g. bench/view.sh samples/scenes/square_12.json 1024x576 36 build/voltree --assets samples/scenes
set -euo pipefail
input=$1 size=${2:-512x512} frames=${3:-36} voltree=${4:-build/voltree}
shift $(($# < 4 ? $# : 4))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# 0.4 degree per pixel of drag (view/orbit_control.cpp): 900 px is one turn.
awk -v n="$frames" 'BEGIN { for (i = 1; i <= n; ++i) printf "%.2f drag %.4f 0\n", 0.5 * i, 900 / n;
                            printf "%.2f quit\n", 0.5 * (n + 1) }' >"$work/orbit.txt"
width=${size%x*} height=${size#*x}
xvfb-run -a -s "-screen 0 $((width + 64))x$((height + 64))x24" \
  "$voltree" view "$input" --size "$size" --no-panel --script "$work/orbit.txt" -o "$work/shots" "$@"
