#!/bin/sh
# make bench-play: player vs floor frames per second (not a pass/fail test).
B=${1:-build}
. bench/lib.sh
echo "machine: $(nproc) cores, $(cpu)"
# both programs run with the same fixed malloc thresholds (bench/lib.sh)
fixed_malloc
f=$($B/bench/play_floor) || exit 1
p=$($B/bench/play_bench) || exit 1
echo "malloc: $GLIBC_TUNABLES"
echo "renderer: $(echo "$p" | sed 's/.*renderer //')"
echo "scene: $(echo "$p" | awk '{print $4}') triangles, 640x480, 200 frames, colour + depth read-back each frame"
ff=$(echo "$f" | awk '{print $2}')
pf=$(echo "$p" | awk '{print $2}')
echo "floor  (one VBO, one draw, 32x32-quad blocks): $ff fps"
echo "player (glsplay renderer):  $pf fps ($(echo "$p" | awk '{print $6}') chunks)"
awk -v f="$ff" -v p="$pf" 'BEGIN { printf "ratio floor/player: %.3f (aim: <= 1.2)\n", f / p }'
