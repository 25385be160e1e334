#!/bin/sh
# Byte-identity guard.  Compiles a fixed set of scenes (the demo, the
# examples, tests/compiler/*, the scene library as a library bundle), dumps
# each bundle with glsdis --source, renders the demo at the README's
# command and one example, and compares the SHA-256 of every bundle, dump,
# depth map and point cloud, and of the decoded pixels of every PNG image,
# with the list in tests/e2e/golden.sha256.  Prints "ok NAME" /
# "FAIL NAME: why", one line per file.
#
# The list was recorded on main before the refactoring of issue 12, which
# must not change a byte.  A later change that legitimately changes a
# bundle, dump or image updates the list in the same commit and says why in
# a comment there:  sh tests/e2e/golden.sh --record  rewrites the digests
# and keeps the comment lines.
#
# Every command runs from the repository root with relative paths: source
# paths are recorded in bundles as spelled (spec/bundle.md, section 14);
# the scene library is compiled as the Makefile compiles it,
# glsc -I $B/textures --lib scenelib.
. tests/e2e/lib.sh
LIST=tests/e2e/golden.sha256

need golden_build_products glsc glsdis glsplay textures
BIN=$(cd "$B" && pwd)

mkdir -p "$t/files"
# bundle NAME GLSC_ARGS...: compile into files/NAME.glsb, dump into files/NAME.dis
bundle() {
    name=$1
    shift
    if ! "$BIN/glsc" "$@" -o "$t/files/$name.glsb" >"$t/err" 2>&1; then
        fail "golden_compile_$name" "$(head -3 "$t/err")"
        return
    fi
    "$BIN/glsdis" --source "$t/files/$name.glsb" >"$t/files/$name.dis" 2>"$t/err" ||
        fail "golden_dump_$name" "$(head -3 "$t/err")"
}

bundle scenelib -I "$B/textures" --lib scenelib
bundle demo -I examples/demo -I "$B/textures" examples/demo/Demo.scene
for e in calibration stereo dense_stereo grouping lane signs; do
    bundle "$e" -I "$t/files/scenelib.glsb" examples/$e/*.scene
done
bundle lang -I tests/compiler/lang tests/compiler/lang/Top.scene
bundle figure7 -I tests/compiler/paper tests/compiler/paper/Figure7.scene
bundle tga_rgb -I tests/compiler/tga_rgb tests/compiler/tga_rgb/Top.scene

# render NAME BUNDLE GLSPLAY_ARGS...: every file glsplay writes, renamed
# files/NAME_CAMERA_FILE
render() {
    name=$1 bundle=$2
    shift 2
    [ -f "$t/files/$bundle.glsb" ] || return
    if ! "$B/glsplay" "$t/files/$bundle.glsb" "$@" -o "$t/out_$name" >"$t/err" 2>&1; then
        fail "golden_render_$name" "$(head -3 "$t/err")"
        return
    fi
    for f in "$t/out_$name"/*/*; do
        cam=$(basename "$(dirname "$f")")
        mv "$f" "$t/files/${name}_${cam}_$(basename "$f")"
    done
}

# docs/scenes.md's "Compile, inspect, play" command (image, depth, points)
render demo demo --camera examples/demo/left.cam --camera examples/demo/right.cam
# an example with textures and anti-aliasing, as examples/render.sh renders it
render signs signs --camera examples/signs/left.cam --aa 4 --outputs image,depth --background 0.55,0.7,0.9
# the other image formats, whose pixels come from the same render through
# other conversions (issue 16: a camera without sensor effects must keep
# every format's bytes): 16-bit PNG from the accumulator, float PFM from a
# single pass
render signs16 signs --camera examples/signs/left.cam --aa 4 --outputs image --image-format png16 --background 0.55,0.7,0.9
render demopfm demo --camera examples/demo/left.cam --outputs image --image-format pfm

# Bundles, dumps, PFM and PLY files: the SHA-256 of the file.  PNG images:
# the SHA-256 of the pixels as cv2.imread decodes them (shape, dtype, then
# the samples), named NAME.png.pixels, so that a change of PNG encoder or
# compression level (issue 14) keeps the digests while any changed pixel
# still fails.
(cd "$t/files" && sha256sum -- *) | grep -v '\.png$' >"$t/got"
/usr/bin/python3 - "$t/files" >>"$t/got" <<'PY' || fail golden_png_pixels "cannot decode the PNG images"
import hashlib, os, sys
import cv2
d = sys.argv[1]
for n in sorted(os.listdir(d)):
    if n.endswith(".png"):
        a = cv2.imread(os.path.join(d, n), cv2.IMREAD_UNCHANGED)
        if a is None:
            sys.exit("cannot read " + n)
        h = hashlib.sha256(("%s %s\n" % (a.shape, a.dtype)).encode() + a.tobytes()).hexdigest()
        print("%s  %s.pixels" % (h, n))
PY

if [ "$1" = --record ]; then
    { grep '^#' "$LIST" 2>/dev/null; cat "$t/got"; } >"$t/list" && cp "$t/list" "$LIST"
    echo "recorded $(wc -l <"$t/got") digests in $LIST"
    exit 0
fi

[ -f "$LIST" ] || { fail golden_list "no $LIST"; exit 0; }
grep -v '^#' "$LIST" | while read -r want name; do
    got=$(awk -v n="$name" '$2 == n { print $1 }' "$t/got")
    if [ -z "$got" ]; then
        fail "golden_$name" "not produced"
    elif [ "$got" = "$want" ]; then
        ok "golden_$name"
    else
        fail "golden_$name" "SHA-256 $got, $LIST records $want"
    fi
done
awk '{ print $2 }' "$t/got" | while read -r name; do
    grep -q "^[0-9a-f]*  $name\$" "$LIST" || fail "golden_$name" "produced but not in $LIST (record it)"
done
