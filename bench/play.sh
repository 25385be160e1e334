#!/bin/sh
# make bench-play: player vs floor frames per second (not a pass/fail test).
B=${1:-build}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
# llvmpipe allocates and frees large bin buffers every frame; with glibc's
# default adaptive mmap threshold a process can end up page-faulting them
# in anew each frame, which swamped the measurement (the floor ran at a
# third of its speed).  Both programs run with the same fixed thresholds.
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=4000000000:glibc.malloc.mmap_threshold=33554432
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
