#!/bin/sh
# glsplay's writer thread (runtime/write/frame_writer.h) and PNG encoding:
# the same files with --writer-threads 1 and 0; PNG pixels exact through
# cv2.imread (8-bit and 16-bit mid-greys); a write that fails mid-sequence
# (a directory in a later frame's place, a full disk) stops the run with
# exit 1 and the usual message, at the same frame with or without the
# thread, with no partial file and no frame record for an incomplete
# frame.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
tmp=$t
mnt=""
trap '[ -n "$mnt" ] && umount "$mnt" 2>/dev/null; rm -rf "$tmp"' EXIT

# a mid-grey quadrilateral with slanted edges (0.5 -> 128 in 8 bits,
# 128 * 257 = 32896 in 16) on a
# background of 0.25 (64), 10 units ahead of the rig
mkdir -p "$tmp/s"
cat >"$tmp/s/Sq.scene" <<'SCENE'
color(0.5, 0.5, 0.5);
poly { vert(-1, -1, 10); vert(1.1, -0.9, 10); vert(1, 1, 10); vert(-1.05, 1.02, 10); }
SCENE
"$BIN/glsc" -I "$tmp/s" -o "$tmp/sq.glsb" Sq || { fail writer_setup "scene does not compile"; exit 0; }
rig_cam "$tmp/cam.cam"
{ f=0; while [ $f -lt 8 ]; do echo "$f $f 1 0 0 0 1 0 0 0 1 0 0 -0.$f"; f=$((f + 1)); done; } >"$tmp/traj.txt"
play() { "$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --trajectory "$tmp/traj.txt" --background 0.25,0.25,0.25 "$@"; }

# the same files, byte for byte, with and without the thread: every output,
# 8-bit, then 16-bit with anti-aliasing and the edges map
same=1
for args in "" "--image-format png16 --aa 4 --outputs image,depth,points,edges"; do
    # shellcheck disable=SC2086
    play $args --writer-threads 1 -o "$tmp/t1" 2>"$tmp/err1" &&
        play $args --writer-threads 0 -o "$tmp/t0" 2>"$tmp/err0" &&
        diff -r "$tmp/t1" "$tmp/t0" >"$tmp/diff" && [ "$(ls -A "$tmp/t1/cam" | wc -l)" -ge 24 ] || same=0
    [ "$same" = 1 ] && [ -z "$args" ] && cp -r "$tmp/t1" "$tmp/png8"
    rm -rf "$tmp/t1" "$tmp/t0"
done
[ "$same" = 1 ] && ok writer_thread_same_files ||
    fail writer_thread_same_files "$(cat "$tmp/err1" "$tmp/err0" "$tmp/diff" 2>/dev/null | head -5)"

# PNG pixels exact (cv2.imread): the 8-bit and 16-bit images of the
# default render (exact coverage) and the 16-bit image of a sampled one
# against the float image of the same render
play --frames 0:1 --image-format png16 --outputs image -o "$tmp/p16" 2>>"$tmp/err"
play --frames 0:1 --image-format pfm --outputs image -o "$tmp/pf" 2>>"$tmp/err"
play --frames 0:1 --image-format png16 --aa 4 --outputs image -o "$tmp/a16" 2>>"$tmp/err"
play --frames 0:1 --image-format pfm --aa 4 --outputs image -o "$tmp/af" 2>>"$tmp/err"
if /usr/bin/python3 - "$tmp" <<'PY'
import sys, cv2, numpy as np
t = sys.argv[1]
p8 = cv2.imread(t + "/png8/cam/image_000000.png", cv2.IMREAD_UNCHANGED)
p16 = cv2.imread(t + "/p16/cam/image_000000.png", cv2.IMREAD_UNCHANGED)
a16 = cv2.imread(t + "/a16/cam/image_000000.png", cv2.IMREAD_UNCHANGED)
af = cv2.imread(t + "/af/cam/image_000000.pfm", cv2.IMREAD_UNCHANGED)
pf = cv2.imread(t + "/pf/cam/image_000000.pfm", cv2.IMREAD_UNCHANGED).astype(np.float64)
ok = p8.dtype == np.uint8 and p8.shape == (48, 64, 3) and p16.dtype == np.uint16
ok = ok and tuple(p8[24, 32]) == (128, 128, 128) and tuple(p8[0, 0]) == (64, 64, 64)
# 8 and 16 bits of the exact image: its float value rounded to nearest
ok = ok and np.array_equal(p8, np.round(pf * 255).astype(np.uint8))
ok = ok and np.array_equal(p16, np.round(pf * 65535).astype(np.uint16))
ok = ok and len(np.unique(p16)) > 3  # the square's edges cut pixels
# 16-bit of the anti-aliased image: round(v * 65535) of the float image
ok = ok and np.array_equal(a16, np.round(af.astype(np.float64) * 65535).astype(np.uint16))
ok = ok and len(np.unique(a16)) > 3  # edge pixels between the greys
sys.exit(0 if ok else 1)
PY
then ok png_pixels_exact_cv2; else fail png_pixels_exact_cv2 "decoded pixels differ from the expected values"; fi

# check_stop DIR RC ERRFILE: the run stopped with exit 1 and one message;
# frames before the failing one complete with their records; the failing
# frame and every later one without record or file (but an obstacle, or
# the failing frame's image written before its depth map); no temporary
# file left.  Prints the failing frame, or returns 1 with why in $tmp/why.
check_stop() {
    dir=$1 rc=$2 errf=$3
    bad=""
    f=0
    while [ $f -lt 8 ]; do
        ff=$(printf %06d $f)
        if [ -f "$dir/cam/.frame_$ff.done" ]; then
            [ -z "$bad" ] || { echo "frame $f has a record after the failing frame $bad" >"$tmp/why"; return 1; }
        else
            [ -n "$bad" ] || bad=$f
            for k in image depth; do
                [ -f "$dir/cam/${k}_$ff.png" ] || [ -f "$dir/cam/${k}_$ff.pfm" ] || continue
                [ "$f" = "$bad" ] && [ "$k" = image ] && continue # written before the failing depth map
                echo "frame $f has a $k file after the failure" >"$tmp/why"
                return 1
            done
        fi
        f=$((f + 1))
    done
    tmps=$(find "$dir" -name '*.tmp*' | wc -l)
    if [ "$rc" != 1 ] || [ "$(wc -l <"$errf")" != 1 ] || [ "$tmps" != 0 ] || [ -z "$bad" ]; then
        echo "rc=$rc, $tmps temporary files, first incomplete frame '$bad', stderr: $(cat "$errf")" >"$tmp/why"
        return 1
    fi
    echo "$bad"
}

# a directory where frame 3's image should go: refused by the writer
for n in 1 0; do
    mkdir -p "$tmp/ob$n/cam/image_000003.png"
    play --outputs image,depth --writer-threads $n -o "$tmp/ob$n" 2>"$tmp/oberr$n"
    echo $? >"$tmp/obrc$n"
done
want="glsplay: error: cannot write $tmp/ob1/cam/image_000003.png: it is a directory"
if ! b1=$(check_stop "$tmp/ob1" "$(cat "$tmp/obrc1")" "$tmp/oberr1") ||
    ! b0=$(check_stop "$tmp/ob0" "$(cat "$tmp/obrc0")" "$tmp/oberr0"); then
    fail writer_error_stops_run "$(cat "$tmp/why")"
elif [ "$b1" = 3 ] && [ "$b0" = 3 ] && [ "$(cat "$tmp/oberr1")" = "$want" ] &&
    [ "$(sed "s|/ob0/|/ob1/|" "$tmp/oberr0")" = "$want" ] && [ ! -e "$tmp/ob1/cam/depth_000003.pfm" ]; then
    ok writer_error_stops_run
else
    fail writer_error_stops_run "stopped at frames '$b1' (thread) and '$b0' (none): $(cat "$tmp/oberr1")"
fi

# a full disk (a 64 KiB tmpfs; needs the right to mount, else said and
# skipped): depth maps of 12 KiB fill it within a few frames
mkdir -p "$tmp/full"
if mount -t tmpfs -o size=64k tmpfs "$tmp/full" 2>/dev/null; then
    mnt="$tmp/full"
    res=""
    for n in 1 0; do
        rm -rf "$tmp/full/out"
        play --outputs depth --writer-threads $n -o "$tmp/full/out" 2>"$tmp/fullerr$n"
        rc=$?
        b=$(check_stop "$tmp/full/out" "$rc" "$tmp/fullerr$n") || { fail writer_disk_full "$(cat "$tmp/why")"; res=x; break; }
        want="glsplay: error: cannot write $tmp/full/out/cam/depth_$(printf %06d "$b").pfm: No space left on device"
        [ "$(cat "$tmp/fullerr$n")" = "$want" ] || { fail writer_disk_full "$(cat "$tmp/fullerr$n"), wanted $want"; res=x; break; }
        res="$res $b"
    done
    case $res in
    x) ;;
    " "[1-7]" "[1-7]) [ "${res% *}" = " ${res##* }" ] && ok writer_disk_full && echo "  full disk at frame${res% *}" ||
        fail writer_disk_full "stopped at frames$res (thread, none)" ;;
    *) fail writer_disk_full "stopped at frames '$res'" ;;
    esac
    umount "$tmp/full" && mnt=""
else
    echo "note: writer_disk_full not run: cannot mount a tmpfs here"
fi

# a bad --writer-threads is a usage error
"$BIN/glsplay" "$tmp/sq.glsb" --camera "$tmp/cam.cam" --writer-threads 2 -o "$tmp/u" 2>"$tmp/uerr"
rc=$?
[ $rc = 2 ] && [ "$(cat "$tmp/uerr")" = "glsplay: error: --writer-threads needs 0 or 1, got '2' (try glsplay --help)" ] &&
    ok writer_threads_usage || fail writer_threads_usage "rc=$rc $(cat "$tmp/uerr")"

# --explain says how the files are encoded and whether the writer thread runs
for n in 1 0; do
    play --writer-threads $n --explain >"$tmp/expl$n" 2>&1
done
w1="files: PNG by libspng, zlib level 1, the \"sub\" filter on every row; each frame's files encoded and written on a thread of their own while the next frame renders (--writer-threads 1), at most 2 frames pending"
w0="files: PNG by libspng, zlib level 1, the \"sub\" filter on every row; each frame's files encoded and written before the next frame renders (--writer-threads 0)"
grep -qxF "$w1" "$tmp/expl1" && grep -qxF "$w0" "$tmp/expl0" && ok writer_explained ||
    fail writer_explained "$(grep '^files:' "$tmp/expl1" "$tmp/expl0")"
