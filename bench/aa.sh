#!/bin/sh
# make bench-aa: seconds per frame and edge-localisation error of the
# anti-aliased player for N = 1..128 (and 256 where AA_BIG=1), box and
# Gaussian filters, 8-bit / 16-bit / float output; writes
# docs/aa_cost.txt (the table) and docs/aa_cost.svg (the plot, made by
# bench/aa_plot.py), with the cost of anisotropic texture filtering
# (bench/aniso.sh) appended; then the per-sample time breakdown.
B=${1:-build}
W=${AA_W:-320}
H=${AA_H:-240}
NS=${AA_NS:-"1 2 4 8 16 32 64 128"}
[ "${AA_BIG:-0}" = 1 ] && NS="$NS 256"
mkdir -p docs
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=4000000000:glibc.malloc.mmap_threshold=33554432
raw=$(mktemp)
trap 'rm -f "$raw"' EXIT
{
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), OSMesa llvmpipe"
echo "scene: 12 white squares on black, rotated 0.3..9.8 degrees, sub-pixel centres, ${W}x${H}"
echo "edge error: per edge, least-squares line through the per-row displacements against the exact"
echo "answer (box: exact pixel area; gauss: exact truncated-Gaussian integral), px; pattern grid"
} >docs/aa_cost.txt
$B/bench/aa_bench table "$W" "$H" $NS >"$raw" || exit 1
{
printf '\n| N | filter | output | s/frame | edge RMS px | edge max px | row RMS px |\n|---|---|---|---|---|---|---|\n'
grep -v '^#' "$raw" | awk '{printf "| %s | %s | %s | %.4f | %.5f | %.5f | %.5f |\n", $1, $2, $3, $4, $5, $6, $7}'
} >>docs/aa_cost.txt
/usr/bin/python3 bench/aa_plot.py "$raw" docs/aa_cost.svg || exit 1
{
printf '\ntextures: one 640x480 frame of the road demo (frame 4, right camera), whole glsplay run\n\n'
sh bench/aniso.sh "$B" || exit 1
} >>docs/aa_cost.txt
cat docs/aa_cost.txt
echo "plot: docs/aa_cost.svg"
echo
echo "per-sample time, N = 32, ${W}x${H} (draw includes glFinish in serial mode):"
for m in "1 1" "0 1" "1 0" "0 0"; do $B/bench/aa_bench breakdown "$W" "$H" 32 $m; done
