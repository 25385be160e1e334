#!/bin/sh
# make bench-compile: compile a generated scene of >= 1M vertices, report
# vertices per second (best of 3 runs) and bundle size against source size.
set -e
B=${1:-build}
. bench/lib.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cc -O2 -o "$dir/gen" bench/gen_scene.c -lm
"$dir/gen" 500 1000 >"$dir/Terrain.scene"
verts=$(grep -c 'vert(' "$dir/Terrain.scene")
src=$(wc -c <"$dir/Terrain.scene")
best=""
for i in 1 2 3; do
    t0=$(date +%s.%N)
    "$B/glsc" -I "$dir" -o "$dir/t.glsb" Terrain
    t1=$(date +%s.%N)
    t=$(echo "$t1 - $t0" | bc -l)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
done
size=$(wc -c <"$dir/t.glsb")
echo "machine: $(nproc) cores, $(cpu)"
echo "scene: $verts vertices, $src bytes of source text"
printf 'compile: %.3f s (best of 3) = %.2f M vertices/s\n' "$best" "$(echo "$verts / $best / 1000000" | bc -l)"
printf 'bundle: %d bytes = %.3f of the source text\n' "$size" "$(echo "$size / $src" | bc -l)"
