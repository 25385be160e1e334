#!/bin/sh
# usage: sh tools/flatten_diff.sh [BIN]
# The instanced player against its reference path, glsplay --flatten
# (spec/bundle.md 9.3, "Images against --flatten"): every camera of every
# example (the road's sequence aside) and the demo's left and right
# cameras, a plain render (one sample a pixel, image and depth), once
# each way.  Prints per example the pixels whose colour differs (and by
# how many levels at most), pixels where only one depth map has a
# surface, and the largest relative depth difference.  Not a pass/fail
# test: the figures go into the spec and docs/scenes.md.
B=${1:-build}
PY=/usr/bin/python3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
for e in calibration dense_stereo demo grouping lane lighting signs stereo; do
    if [ $e = demo ]; then
        roots="-I examples/demo -I $B/textures"
        cams="left right"
    else
        roots="-I $B/scenelib.glsb"
        cams=$(cd examples/$e && ls *.cam | sed 's/\.cam$//')
    fi
    "$B/glsc" $roots -o "$t/$e.glsb" examples/$e/*.scene || exit 1
    set --
    for c in $cams; do set -- "$@" --camera examples/$e/$c.cam; done
    "$B/glsplay" "$t/$e.glsb" "$@" --outputs image,depth -o "$t/$e/inst" >/dev/null || exit 1
    "$B/glsplay" "$t/$e.glsb" "$@" --outputs image,depth --flatten -o "$t/$e/flat" >/dev/null || exit 1
done
$PY - "$t" <<'PYEOF'
import os, sys
import cv2
import numpy as np

t = sys.argv[1]


def pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        a = np.frombuffer(f.read(), "<f4" if scale < 0 else ">f4")
    return a.reshape(h, w, 3 if kind == b"PF" else 1)


print("example | cameras | pixels | colour differs | by at most (levels) | surface in one depth map only | depth, largest relative difference")
for e in sorted(d for d in os.listdir(t) if os.path.isdir(os.path.join(t, d))):
    cams = sorted(os.listdir(os.path.join(t, e, "inst")))
    n = differ = most = cover = 0
    rel = 0.0
    for c in cams:
        a = cv2.imread(os.path.join(t, e, "inst", c, "image_000000.png"), cv2.IMREAD_UNCHANGED).astype(int)
        b = cv2.imread(os.path.join(t, e, "flat", c, "image_000000.png"), cv2.IMREAD_UNCHANGED).astype(int)
        d = np.abs(a - b).max(axis=2)
        n += d.size
        differ += int((d > 0).sum())
        most = max(most, int(d.max()))
        za = pfm(os.path.join(t, e, "inst", c, "depth_000000.pfm"))
        zb = pfm(os.path.join(t, e, "flat", c, "depth_000000.pfm"))
        fa, fb = np.isfinite(za), np.isfinite(zb)
        cover += int((fa != fb).sum())
        both = fa & fb
        if both.any():
            rel = max(rel, float((np.abs(za[both] - zb[both]) / np.abs(zb[both])).max()))
    print("%s | %d | %d | %d | %d | %d | %.2g" % (e, len(cams), n, differ, most, cover, rel))
PYEOF
