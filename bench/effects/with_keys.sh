#!/bin/sh
# usage: with_keys.sh CAMERA KEYS: print the camera file CAMERA with the
# keys of the file KEYS in place of its keys of the same name (a fisheye's
# fx, fy) and added otherwise; for bench/effects.sh's cases and the
# gallery's lenses (bench/effects_o9/gallery.sh), whose keys files
# (bench/effects/*.keys) are written for any camera.  A camera file may
# not give a key twice, so appending is not enough.
[ $# -eq 2 ] && [ -r "$1" ] && [ -r "$2" ] || { echo "usage: with_keys.sh CAMERA KEYS (readable files)" >&2; exit 2; }
awk 'NR == FNR { if ($1 !~ /^#/ && NF) k[$1] = 1; next } !($1 in k)' "$2" "$1" && cat "$2"
