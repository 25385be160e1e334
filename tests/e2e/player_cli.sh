#!/bin/sh
# End-to-end tests of build/glsplay: outputs read back with OpenCV,
# orientation, errors, no partial files.  Scenes come from
# build/tests/test_player --write (bundles built in C, no compiler needed).
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
# expect NAME STATUS PATTERN -- command...: exit status, and stderr that is
# one line, or (an error in a text input file) the message line, the
# offending source line and a caret line under the column.
expect() {
    name=$1 want=$2 pat=$3
    shift 4
    "$@" >"$t/stdout" 2>"$t/stderr"
    rc=$?
    lines=$(wc -l <"$t/stderr")
    if [ $rc -ne "$want" ]; then fail "$name" "exit $rc, wanted $want: $(cat "$t/stderr")"
    elif [ -n "$pat" ] && ! grep -q -- "$pat" "$t/stderr"; then fail "$name" "stderr lacks '$pat': $(cat "$t/stderr")"
    elif [ "$want" -ne 0 ] && [ "$lines" -ne 1 ] &&
        ! { [ "$lines" -eq 3 ] && tail -1 "$t/stderr" | grep -q '^[[:space:]]*^$' &&
            head -1 "$t/stderr" | grep -q ':[0-9]*:[0-9]*: error: '; }; then
        fail "$name" "$lines lines of error output: $(cat "$t/stderr")"
    else ok "$name"; fi
}

[ -x "$PLAY" ] || { fail player_cli "no $PLAY"; exit 0; }
$B/tests/test_player --write "$t" >/dev/null || { fail player_cli "cannot write test scenes"; exit 0; }

# one sample a pixel (--aa 1): check_player.py proj holds GL's pixel
# centres to its model (the default, exact coverage, has its own tests)
expect player_renders 0 "" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" --aa 1 -o "$t/out"
for f in image_000000.png depth_000000.pfm points_000000.ply; do
    [ -s "$t/out/proj/$f" ] && ok "player_writes_$f" || fail "player_writes_$f" "missing"
done
if [ -x $PY ] && $PY -c 'import cv2' 2>/dev/null; then
    $PY tests/py/check_player.py proj "$t" "$t/out"
    expect player_orient_stereo 0 "" -- $PLAY "$t/orient.glsb" --camera "$t/orient.cam" \
        --camera "$t/left.cam" --camera "$t/right.cam" -o "$t/out"
    $PY tests/py/check_player.py orient "$t" "$t/out"
    $PY tests/py/check_player.py stereo "$t" "$t/out"
else
    fail player_opencv "no OpenCV under $PY"
fi

# determinism: same inputs, same bytes (one sample a pixel, and the
# default, exact coverage, drawn by threads that share its bands out)
$PLAY "$t/proj.glsb" --camera "$t/proj.cam" --aa 1 -o "$t/again" 2>/dev/null
$PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/def1" 2>/dev/null
$PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/def2" 2>/dev/null
if cmp -s "$t/out/proj/image_000000.png" "$t/again/proj/image_000000.png" &&
   cmp -s "$t/out/proj/depth_000000.pfm" "$t/again/proj/depth_000000.pfm" &&
   cmp -s "$t/out/proj/points_000000.ply" "$t/again/proj/points_000000.ply" &&
   [ -s "$t/def1/proj/image_000000.png" ] && cmp -s "$t/def1/proj/image_000000.png" "$t/def2/proj/image_000000.png" &&
   cmp -s "$t/def1/proj/points_000000.ply" "$t/def2/proj/points_000000.ply"; then
    ok player_deterministic
else fail player_deterministic "outputs differ between runs"; fi

# --outputs: only what is asked for
expect player_outputs_image 0 "" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/img" --outputs image
[ -f "$t/img/proj/image_000000.png" ] && [ ! -e "$t/img/proj/depth_000000.pfm" ] && [ ! -e "$t/img/proj/points_000000.ply" ] &&
    ok player_outputs_only_image || fail player_outputs_only_image "$(ls "$t/img/proj")"
# --size overrides the camera's size
expect player_size 0 "" -- $PLAY "$t/orient.glsb" --camera "$t/orient.cam" -o "$t/sz" --size 64x40 --outputs depth
head -c 12 "$t/sz/orient/depth_000000.pfm" | tr '\n' ' ' | grep -q '^Pf 64 40 ' && ok player_size_pfm_header ||
    fail player_size_pfm_header "$(head -c 12 "$t/sz/orient/depth_000000.pfm")"

# --explain alone: the plan, no rendering, no output directory
expect player_explain 0 "" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" --explain
grep -q "textures *off" "$t/stdout" && grep -q "reads back: colour" "$t/stdout" && grep -q "reversed-Z" "$t/stdout" &&
    ok player_explain_plan || fail player_explain_plan "$(cat "$t/stdout")"
expect player_explain_depth_only 0 "" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" --explain --outputs depth
grep -q "reads back: depth (float32) *$" "$t/stdout" && ok player_explain_no_colour_readback ||
    fail player_explain_no_colour_readback "$(grep 'reads back' "$t/stdout")"

# errors: one line, status 1 (input) or 2 (usage), no files left behind
printf 'width 10\nheight 10\nfx 1\nfy 1\ncx 1\ncy 1\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 1\nfar 0.5\n' >"$t/bad.cam"
printf 'width 10\nheight 10\nfx 1\nfy 1\ncx 1\ncy 1\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 1\nfra 2\n' >"$t/typo.cam"
expect player_err_camera_missing 1 "nope.cam: error: cannot open" -- $PLAY "$t/proj.glsb" --camera "$t/nope.cam" -o "$t/e1"
expect player_err_camera_bad 1 "bad.cam:10:5: error: far" -- $PLAY "$t/proj.glsb" --camera "$t/bad.cam" -o "$t/e2"
expect player_err_camera_typo 1 "did you mean 'far'" -- $PLAY "$t/proj.glsb" --camera "$t/typo.cam" -o "$t/e3"
# a bad second camera: nothing is written for the good first one
expect player_err_second_camera 1 "bad.cam" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" --camera "$t/bad.cam" -o "$t/e4"
[ ! -e "$t/e4" ] && ok player_err_no_partial_output || fail player_err_no_partial_output "$(find "$t/e4")"
cp "$t/proj.glsb" "$t/corrupt.glsb"
printf '\377\377\377\377' | dd of="$t/corrupt.glsb" bs=1 seek=100 conv=notrunc 2>/dev/null
expect player_err_corrupt_bundle 1 "glsplay: error: .*corrupt.glsb" -- $PLAY "$t/corrupt.glsb" --camera "$t/proj.cam" -o "$t/e5"
head -c 20 "$t/proj.glsb" >"$t/short.glsb"
expect player_err_truncated_bundle 1 "glsplay: error:" -- $PLAY "$t/short.glsb" --camera "$t/proj.cam" -o "$t/e6"
expect player_err_library_bundle 1 "library bundle" -- $PLAY "$t/library.glsb" --camera "$t/proj.cam" -o "$t/e7"
touch "$t/afile"
expect player_err_unwritable_output 1 "cannot create output directory" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/afile/out"
[ -z "$(find "$t" -name '*.tmp*' -o -name '.*.tmp')" ] && ok player_err_no_temp_files || fail player_err_no_temp_files "$(find "$t" -name '*tmp*')"
for e in e1 e2 e3 e5 e6 e7; do [ -e "$t/$e" ] && { fail player_err_created_$e "output directory created on error"; }; done
expect player_usage_no_args 2 "no bundle" -- $PLAY
expect player_usage_no_camera 2 "no camera" -- $PLAY "$t/proj.glsb" -o "$t/u"
expect player_usage_bad_size 2 "WxH" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/u" --size 0x10
expect player_usage_bad_outputs 2 "image, depth, points" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/u" --outputs image,colour
expect player_usage_unknown_option 2 "unknown option" -- $PLAY "$t/proj.glsb" --frobnicate
expect player_usage_motion_flatten 2 "glsplay: error: --motion moves instances, and --flatten draws none; leave out --flatten (try glsplay --help)" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/u" --flatten --motion car=x.txt
expect player_help 0 "" -- $PLAY --help
grep -q "usage: glsplay" "$t/stdout" && ok player_help_text || fail player_help_text "no usage line"

# exact (lib.sh) from here: stderr exactly LINE, and as many lines
EXACT_LINES=1
# -o "": OUTDIR/NAME would be /NAME at the file-system root
exact player_usage_empty_outdir 2 "glsplay: error: -o needs a non-empty output directory (try glsplay --help)" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o ""
# an edges map of one sample per pixel would be all 0: refused
exact player_usage_edges_without_aa 2 \
    "glsplay: error: --outputs edges needs anti-aliasing, --aa N with N > 1 (try glsplay --help)" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/m" --outputs image,edges
exact player_usage_edges_aa1 2 \
    "glsplay: error: --outputs edges needs anti-aliasing, --aa N with N > 1 (try glsplay --help)" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/m" --outputs edges --aa 1
exact player_usage_mask_aa1 2 \
    "glsplay: error: --outputs mask needs anti-aliasing, --aa N with N > 1 (try glsplay --help)" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/m" --outputs mask --aa 1
[ ! -e "$t/m" ] && ok player_edges_without_aa_writes_nothing || fail player_edges_without_aa_writes_nothing "$(find "$t/m")"
exact player_edges_with_aa 0 "" -- $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/m2" --outputs edges --aa 2
[ "$(ls "$t/m2/proj")" = "edges_000000.png" ] && ok player_edges_file_name || fail player_edges_file_name "$(ls "$t/m2/proj")"
# mask: edges' old name, for one release: the same map as mask_F.png, and a note
exact player_mask_alias 0 \
    "glsplay: note: --outputs mask is now called edges (the word mask will mean object masks); mask_F.png is written as before" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/m3" --outputs mask --aa 2
[ "$(ls "$t/m3/proj")" = "mask_000000.png" ] && cmp -s "$t/m3/proj/mask_000000.png" "$t/m2/proj/edges_000000.png" &&
    ok player_mask_alias_same_map || fail player_mask_alias_same_map "$(ls "$t/m3/proj")"
# anisotropic texture filtering: off in the default plan (llvmpipe takes
# minutes per frame with it), on with --anisotropic N
if "$B/glsc" -I examples/demo -I "$B/textures" -o "$t/tex.glsb" examples/demo/Demo.scene 2>"$t/stderr"; then
    $PLAY "$t/tex.glsb" --camera examples/demo/left.cam --explain >"$t/plan" 2>&1
    $PLAY "$t/tex.glsb" --camera examples/demo/left.cam --explain --anisotropic 16 >"$t/plan16" 2>&1
    grep -q "GL: anisotropic filtering off" "$t/plan" && ! grep -q "anisotropic filtering up to" "$t/plan" &&
        ok player_explain_anisotropic_off || fail player_explain_anisotropic_off "$(grep -i aniso "$t/plan")"
    grep -q "GL: anisotropic filtering up to 16x (--anisotropic 16)" "$t/plan16" &&
        ok player_explain_anisotropic_on || fail player_explain_anisotropic_on "$(grep -i aniso "$t/plan16")"
else
    fail player_explain_anisotropic "the demo scene does not compile: $(cat "$t/stderr")"
fi
exact player_usage_anisotropic 2 "glsplay: error: --anisotropic needs N in 1..16, got '32' (try glsplay --help)" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/u" --anisotropic 32
# every option with a fixed set of words names itself, its words, what was
# given, and the likely typo (base/choice.h; issue 26)
H=" (try glsplay --help)"
U="$PLAY $t/proj.glsb --camera $t/proj.cam -o $t/u"
OUTS="image, depth, points, edges, disparity, disparity16, depth16, landmarks, instance, class, coco, normals, flow, boxes, coverage, edge_segments"
exact player_choice_progress_word 2 "glsplay: error: --progress takes one of: bar, json (not 'xml')$H" -- $U --progress xml
exact player_choice_progress_equals 2 "glsplay: error: --progress takes one of: bar, json (not 'xml')$H" -- $U --progress=xml
exact player_choice_progress_typo 2 "glsplay: error: --progress takes one of: bar, json (not 'jsno'); did you mean 'json'?$H" -- \
    $U --progress jsno
exact player_choice_progress_empty 2 "glsplay: error: --progress takes one of: bar, json (not '')$H" -- $U --progress=
exact player_choice_outputs_typo 2 \
    "glsplay: error: --outputs takes a comma-separated list of: $OUTS (not 'dpeth'); did you mean 'depth'?$H" -- \
    $U --outputs image,dpeth
exact player_choice_outputs_far 2 "glsplay: error: --outputs takes a comma-separated list of: $OUTS (not 'colour')$H" -- \
    $U --outputs image,colour
exact player_choice_outputs_empty 2 "glsplay: error: --outputs needs a comma-separated list of: $OUTS$H" -- $U --outputs ,
exact player_choice_pattern 2 "glsplay: error: --pattern takes one of: lattice, grid, stratified (not 'gird'); did you mean 'grid'?$H" -- \
    $U --pattern gird
exact player_choice_pattern_missing 2 "glsplay: error: --pattern needs one of: lattice, grid, stratified$H" -- $U --pattern
exact player_choice_filter 2 "glsplay: error: --filter takes one of: box, gauss, gauss:SIGMA (not 'gaus'); did you mean 'gauss'?$H" -- \
    $U --filter gaus
exact player_choice_occlusion 2 "glsplay: error: --occlusion takes one of: auto, on, off (not 'yes')$H" -- $U --occlusion yes
exact player_choice_image_format 2 "glsplay: error: --image-format takes one of: png8, png16, pfm (not 'png32'); did you mean 'png8'?$H" -- \
    $U --image-format png32
exact player_choice_float_format 2 "glsplay: error: --float-format takes one of: pfm, npy (not 'npz'); did you mean 'npy'?$H" -- \
    $U --float-format npz
exact player_choice_backend 2 \
    "glsplay: error: --backend takes one of: auto, egl, egl-device, egl-surfaceless, osmesa (not 'osmsea'); did you mean 'osmesa'?$H" -- \
    $U --backend osmsea
# the values still taken: json before the bundle, after it, as =json; bar
# (a single render draws no bar: nothing on stderr) and --progress alone
# before a bundle path
B1=$t/proj.glsb
progress_ok() { # NAME WANT ARGS...: exit 0; WANT json: the end line, else an empty stderr
    name=$1 want=$2
    shift 2
    $PLAY "$@" --camera "$t/proj.cam" -o "$t/p" --outputs depth 2>"$t/stderr"
    rc=$?
    if [ "$want" = json ]; then grep -q '"event": "end", "status": "ok"' "$t/stderr"; else [ ! -s "$t/stderr" ]; fi
    seen=$?
    [ $rc -eq 0 ] && [ $seen -eq 0 ] && ok "$name" || fail "$name" "exit $rc: $(cat "$t/stderr")"
}
progress_ok player_progress_json_before json --progress json "$B1"
progress_ok player_progress_json_after json "$B1" --progress json
progress_ok player_progress_json_equals json "$B1" --progress=json
progress_ok player_progress_bar_before bar --progress bar "$B1"
progress_ok player_progress_bar_equals bar "$B1" --progress=bar
progress_ok player_progress_alone_before_bundle bar --progress "$B1"
# exit status (spec/exit_status.md): what the command line alone shows is a
# usage error, 2, found before any file is read; what a file shows, 1
mkdir -p "$t/sub"
cp "$t/proj.cam" "$t/sub/proj.cam"
exact player_status_cameras_same_name 2 \
    "glsplay: error: cameras $t/proj.cam and $t/sub/proj.cam would both write to $t/s1/proj/$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" --camera "$t/sub/proj.cam" -o "$t/s1"
exact player_status_camera_no_name 2 "glsplay: error: $t/sub/: cannot name an output directory after this camera file$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/sub/" -o "$t/s1"
exact player_status_disparity_one_camera 2 \
    "glsplay: error: --outputs disparity needs a rectified pair: exactly two cameras, the left one first; 1 given$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s1" --outputs disparity
exact player_status_flow_without_trajectory 2 \
    "glsplay: error: --outputs flow needs a --trajectory: the flow goes from each frame to the next$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s1" --outputs flow
exact player_status_gauss_sigma 2 "glsplay: error: Gaussian sigma 100 is outside 0.01..16 pixels$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s1" --aa 2 --filter gauss:100
exact player_status_motion_twice 2 "glsplay: error: --motion car=b.txt: instance car is moved twice$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s1" --motion car=a.txt --motion car=b.txt
exact player_status_empty_bundle 2 "glsplay: error: an empty bundle name$H" -- $PLAY "" --camera "$t/proj.cam" -o "$t/s1"
exact player_status_empty_trajectory 2 "glsplay: error: --trajectory needs a trajectory file$H" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s1" --trajectory ""
# both kinds: the usage error, and no file is read (the camera is missing)
exact player_status_usage_first 2 \
    "glsplay: error: --outputs disparity needs a rectified pair: exactly two cameras, the left one first; 1 given$H" -- \
    $PLAY "$t/nope.glsb" --camera "$t/nope.cam" -o "$t/s1" --outputs disparity
[ ! -e "$t/s1" ] && ok player_status_usage_writes_nothing || fail player_status_usage_writes_nothing "$(find "$t/s1")"
# a --motion NAME the bundle lacks: only the bundle says so, exit 1
expect player_status_motion_unknown_instance 1 "has no instance named 'car'" -- \
    $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/s2" --motion car=a.txt
# an image too large for memory: which framebuffer, how much memory, and
# the option that lowers it (memory capped at 1.5 GB with ulimit -v; not
# under ASan, which reserves far more address space than that)
if [ "$GLS_SANITIZED" != 1 ]; then
    exact player_err_mosaic_memory 1 \
        "glsplay: error: camera proj: cannot allocate a 16000x16000 framebuffer, 16x16 tiles of 1000x1000 images (1.9 GiB of memory); lower --aa-tiles (256 tiles a pass now)" -- \
        sh -c 'ulimit -v 1500000; exec "$@"' sh $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/mem" \
        --size 1000x1000 --aa 16 --aa-tiles 256 --pattern stratified --outputs image
    exact player_err_image_memory 1 \
        "glsplay: error: camera proj: cannot allocate a 16384x16384 framebuffer (3.0 GiB of memory); lower --size (or the camera's width and height)" -- \
        sh -c 'ulimit -v 1500000; exec "$@"' sh $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/mem" \
        --size 16384x16384 --outputs image --aa 1
    # the default, exact coverage: its float image and the file's, planned
    exact player_err_image_memory_exact 1 \
        "glsplay: error: camera proj: out of memory for the buffers of a 16384x16384 image (about 6.0 GiB); lower --size (or the camera's width and height)" -- \
        sh -c 'ulimit -v 1500000; exec "$@"' sh $PLAY "$t/proj.glsb" --camera "$t/proj.cam" -o "$t/mem" \
        --size 16384x16384 --outputs image
fi
