#!/bin/sh
# A rolling shutter draws and reads, for each band of rows, only the rows
# it needs (spec/outputs.md "With a rolling shutter", "Through a lens"):
# through a lens the fine rows its pixels read (runtime/effects/distort_exposure.c,
# gls_distort_truth_bands), through a pinhole the band's own rows
# (runtime/play/play_passes.c play_centre_bands; the image's bands: one sample a pixel,
# or a lattice plan's fine tiles, aa_onepass.c, or the jittered passes,
# aa_render.c; gt_flow_rolling.c for the
# next frame's depth).  Every output must be the
# same bytes as with each band drawing and reading the whole image
# ($B/glsplay_bands_whole, glsplay's run with gls_play_opts' bands_whole
# set, tools/glsplay_bands_whole.c: a parameter of the API, never read
# from the environment; tests/e2e/env_switches.sh).  The scene
# of tests/py/flow_scene.py (a moving box: ids, normals, flow, boxes),
# every output each camera allows.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
need rolling_bands_setup glsplay glsplay_bands_whole
if ! $PY tests/py/flow_scene.py "$t" 2>"$t/err" ||
    ! "$BIN/glsc" -I "$BIN/scenelib.glsb" -o "$t/f.glsb" "$t/Flow.scene" 2>>"$t/err"; then
    echo "FAIL rolling_bands_setup: $(cat "$t/err")"
    exit 0
fi
# the scene's camera at 160x120, each row read 1/120 of a frame after the
# one above
sed -e 's/^width .*/width 160/' -e 's/^height .*/height 120/' -e 's/^fx .*/fx 150/' -e 's/^fy .*/fy 150/' \
    -e 's/^cx .*/cx 79.5/' -e 's/^cy .*/cy 59.5/' "$t/cam.cam" >"$t/base.cam"
{ cat "$t/base.cam"; printf 'line_delay 0.008333\ndistortion -0.25 0.02 0.001 -0.001\n'; } >"$t/brown.cam"
{ cat "$t/base.cam"; printf 'line_delay 0.008333\nfisheye 0.05 -0.01 0.002 -0.0004\n'; } >"$t/fish.cam"
{ cat "$t/base.cam"; printf 'line_delay 0.008333\n'; } >"$t/pin.cam"
# with depth of field too: each lens point's bands (a motion blur would
# need poses before frame 0)
{ cat "$t/base.cam"; printf 'line_delay 0.008333\naperture 0.05\nfocus 6\nexposure_samples 3\n'; } \
    >"$t/combo.cam"
# same NAME WANT OPTIONS...: frame 0 (its flow reads frame 1's rows) with
# the rows narrowed and with the whole image, WANT files, the same bytes
same() {
    name=$1 want=$2
    shift 2
    for how in rows whole; do
        [ $how = whole ] && play=glsplay_bands_whole || play=glsplay
        if ! "$BIN/$play" "$t/f.glsb" --trajectory "$t/trajectory.txt" \
            --motion "mover=$t/mover.txt" --frames 0:1 -o "$t/$name.$how" "$@" 2>"$t/$name.err"; then
            echo "FAIL $name: glsplay failed: $(cat "$t/$name.err")"
            return
        fi
        (cd "$t/$name.$how" && find . -type f | sort) >"$t/$name.$how.list"
    done
    n=$(wc -l <"$t/$name.rows.list")
    differ=""
    while read -r f; do
        cmp -s "$t/$name.rows/$f" "$t/$name.whole/$f" || differ="$differ $f"
    done <"$t/$name.rows.list"
    if ! cmp -s "$t/$name.rows.list" "$t/$name.whole.list"; then
        echo "FAIL $name: not the same files: $(diff "$t/$name.rows.list" "$t/$name.whole.list" | tr '\n' ' ')"
    elif [ "$n" -ne "$want" ]; then
        echo "FAIL $name: $n files, want $want: $(tr '\n' ' ' <"$t/$name.rows.list")"
    elif [ -n "$differ" ]; then
        echo "FAIL $name: differ:$differ"
    else
        echo "ok $name"
    fi
}
ALL=image,depth,points,instance,normals,flow,boxes
# each camera: image depth points instance instances.json normals
# boxes.txt boxes.json flow.flo flow.png flowmask .done (12), with landmarks
# or edges 13
same lens_bands_same_bytes 24 --camera "$t/brown.cam" --camera "$t/fish.cam" --outputs $ALL
# one sample a pixel: the image's bands narrowed too
same pinhole_bands_same_bytes 26 --camera "$t/pin.cam" --camera "$t/combo.cam" --outputs $ALL,landmarks
# anti-aliased (the lattice's fine tiles narrowed to each band's samples)
same pinhole_bands_aa_same_bytes 26 --camera "$t/pin.cam" --camera "$t/combo.cam" --aa 2 --outputs $ALL,edges
# jittered passes (stratified; the grid with the Gaussian, whose samples
# reach past the pixel): each pass of the mosaic narrowed to the band's
# rows
same pinhole_bands_stratified_same_bytes 13 --camera "$t/pin.cam" --aa 2 --pattern stratified --outputs $ALL,edges
same pinhole_bands_gauss_same_bytes 13 --camera "$t/pin.cam" --aa 2 --pattern grid --filter gauss --outputs $ALL,edges
