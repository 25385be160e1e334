#!/bin/sh
# Render the paper-figure examples (examples/*/README.md) into OUTDIR/<example>/.
# usage: render.sh BIN OUTDIR [GALLERYDIR]
#   BIN: build directory with glsc, glsplay, depth2png, pnghalf, scenelib.glsb
#   GALLERYDIR: also write GALLERYDIR/ex_<example>.png and ex_<example>_depth.png
#   (one camera per example, 320 x 240)
# Each example is one top-level scene, compiled against the scene library,
# and rendered through every camera file in its directory; every camera's
# depth map is also shown in colour as depth_000000_view.png.
# Environment (the tests use these to render quickly; the defaults are what
# `make demo` renders):
#   EXAMPLES_LOOK_AA=N   anti-aliasing of the examples where it is only for
#                        looks (stereo, grouping, lane, signs; default 4);
#                        calibration (--aa 8 --pattern grid, the paper's) and
#                        dense_stereo (--aa 4) keep theirs: their tests
#                        measure with them
#   EXAMPLES_OUTPUTS=L   glsplay --outputs (default image,depth,points;
#                        calibration never writes points; stereo's
#                        binocular pair adds disparity,disparity16)
#   EXAMPLES_DEPTH_VIEW=0  skip the colour depth views (no depth2png needed)
#   EXAMPLES_ONLY="a b"  render only these examples
set -e
B=$1
OUT=$2
GAL=$3
[ -n "$B" ] && [ -n "$OUT" ] || { echo "usage: render.sh BIN OUTDIR [GALLERYDIR]" >&2; exit 2; }
HERE=$(dirname "$0")
SKY=0.55,0.7,0.9
LOOK_AA=${EXAMPLES_LOOK_AA:-4}
OUTPUTS=${EXAMPLES_OUTPUTS:-image,depth,points}

# example NAME SCENE GALLERY_CAMERA GLSPLAY_OPTIONS...
example() {
    name=$1 scene=$2 gcam=$3
    shift 3
    case " ${EXAMPLES_ONLY:-$name} " in *" $name "*) ;; *) return 0 ;; esac
    mkdir -p "$OUT/$name"
    "$B/glsc" -I "$B/scenelib.glsb" -o "$OUT/$name/$name.glsb" "$HERE/$name/$scene.scene"
    set -- "$@" -o "$OUT/$name"
    # CAMS: only these cameras (names without .cam), else every camera
    cams=${CAMS:-$(cd "$HERE/$name" && ls *.cam | sed 's/\.cam$//')}
    for c in $cams; do set -- "$@" --camera "$HERE/$name/$c.cam"; done
    "$B/glsplay" "$OUT/$name/$name.glsb" "$@"
    [ "${EXAMPLES_DEPTH_VIEW:-1}" = 0 ] || for c in $cams; do
        d="$OUT/$name/$c"
        "$B/depth2png" "$d/depth_000000.pfm" "$d/depth_000000_view.png"
    done
    if [ -n "$GAL" ] && [ -n "$gcam" ]; then
        "$B/pnghalf" "$OUT/$name/$gcam/image_000000.png" "$GAL/ex_$name.png"
        "$B/pnghalf" "$OUT/$name/$gcam/depth_000000_view.png" "$GAL/ex_${name}_depth.png"
    fi
    echo "$name: $OUT/$name"
}

example calibration Calibration view05 --aa 8 --pattern grid --outputs "$(echo "$OUTPUTS" | sed 's/,*points//')"
# stereo: the binocular rig is a rectified pair, so it also writes its
# disparity (spec/outputs.md); the trinocular rig is rendered on its own
CAMS="bino_left bino_right"
example stereo Stereo bino_left --aa "$LOOK_AA" --outputs "$OUTPUTS,disparity,disparity16" --background $SKY
CAMS="tri_left tri_right tri_top"
example stereo Stereo "" --aa "$LOOK_AA" --outputs "$OUTPUTS" --background $SKY
CAMS=
example dense_stereo DenseStereo left --aa 4 --outputs "$OUTPUTS"
example grouping Grouping left --aa "$LOOK_AA" --outputs "$OUTPUTS" --background $SKY
example lane Lane left --aa "$LOOK_AA" --outputs "$OUTPUTS" --background $SKY
example signs Signs left --aa "$LOOK_AA" --outputs "$OUTPUTS" --background $SKY
example lighting Lighting left --aa "$LOOK_AA" --outputs "$OUTPUTS" --background $SKY
