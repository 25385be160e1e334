#!/bin/sh
# Inputs that never end or are not what they claim: every reader stops
# after a bounded amount of time and memory with a message that names the
# real problem (text lines longer than 4095 bytes, text files over their
# size limit, bundles whose header is wrong, inputs that are not regular
# files).
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
"$BIN/glsc" -I tests/compiler/lang -o "$t/leaf.glsb" pkg.Leaf || { fail input_bounds_setup "glsc"; exit 0; }
CAM=examples/demo/left.cam

# expect NAME STATUS EXACT-FIRST-STDERR-LINE MAX-KIB -- command...
# The command runs under a 60 s timeout; its peak memory must stay under
# MAX-KIB (not checked under ASan, whose shadow memory is large).
expect() {
    name=$1 want=$2 msg=$3 kib=$4
    shift 5
    /usr/bin/time -f %M -o "$t/rss" timeout 60 "$@" >"$t/stdout" 2>"$t/stderr"
    rc=$?
    rss=$(tail -1 "$t/rss")
    if [ $rc -ne "$want" ]; then fail "$name" "exit $rc, wanted $want: $(head -3 "$t/stderr")"
    elif [ "$(head -1 "$t/stderr")" != "$msg" ]; then fail "$name" "stderr '$(head -1 "$t/stderr")', wanted '$msg'"
    elif [ "$GLS_SANITIZED" != 1 ] && [ "$rss" -gt "$kib" ]; then fail "$name" "peak memory $rss KiB, over $kib KiB"
    else ok "$name"; fi
}

# text inputs: an endless line, an endless file (1 GiB of zeros in a
# sparse file: inputs are regular files, so /dev/zero itself is refused
# before anything is read, below)
truncate -s 1G "$t/zeros"
expect trajectory_endless_line 1 "$t/zeros:1: error: line longer than 4095 bytes" 200000 -- \
    "$BIN/glsplay" "$t/leaf.glsb" --camera examples/road/rig/left.cam --trajectory "$t/zeros" -o "$t/o1"
expect camera_endless_file 1 "$t/zeros: error: camera file larger than 1 MiB (1073741824 bytes)" 200000 -- \
    "$BIN/glsplay" "$t/leaf.glsb" --camera "$t/zeros" -o "$t/o2"
expect road_endless_file 1 "$t/zeros: error: road description larger than 16 MiB (1073741824 bytes)" 200000 -- \
    "$BIN/glsroad" "$t/zeros" -o "$t/o3"
expect road_camera_at_endless_trajectory 1 "$t/zeros:1: error: line longer than 4095 bytes" 200000 -- \
    "$BIN/glsroad" --camera-at 0 "$t/zeros" examples/road/rig/left.cam
rm -f "$t/zeros"
expect camera_device 1 "/dev/zero: error: cannot read: it is a character device, not a regular file" 200000 -- \
    "$BIN/glsplay" "$t/leaf.glsb" --camera /dev/zero -o "$t/o2"
expect road_device 1 "/dev/zero: error: cannot read: it is a character device, not a regular file" 200000 -- \
    "$BIN/glsroad" /dev/zero -o "$t/o3"
mkdir "$t/dir"
expect camera_directory 1 "$t/dir: error: is a directory, not a camera file" 200000 -- \
    "$BIN/glsplay" "$t/leaf.glsb" --camera "$t/dir" -o "$t/o4"
expect trajectory_directory 1 "$t/dir: error: is a directory, not a trajectory file" 200000 -- \
    "$BIN/glsplay" "$t/leaf.glsb" --camera examples/road/rig/left.cam --trajectory "$t/dir" -o "$t/o5"
# a road description line over the limit: reported where it overflows
{ printf 'point 0 0 0\n# '; head -c 5000 /dev/zero | tr '\0' x; printf '\n'; } >"$t/long.road"
expect road_long_line 1 "$t/long.road:2:4096: error: line longer than 4095 bytes" 200000 -- \
    "$BIN/glsroad" "$t/long.road" -o "$t/o6"
[ "$(sed -n 3p "$t/stderr" | tr -d ' ')" = "^" ] && [ "$(sed -n 2p "$t/stderr" | cut -c1-6)" = "...xxx" ] &&
    ok road_long_line_excerpt || fail road_long_line_excerpt "$(cat "$t/stderr")"

# bundles: the header is checked against the file's size before the rest
# is read, and only regular files are read (a FIFO must not block; every
# input's FIFO: input_files.sh)
mkfifo "$t/fifo"
expect bundle_fifo 1 "glsplay: error: $t/fifo: cannot read: it is a FIFO (named pipe), not a regular file" 200000 -- \
    "$BIN/glsplay" "$t/fifo" --camera "$CAM" --explain
expect bundle_fifo_glsdis 1 "glsdis: error: $t/fifo: cannot read: it is a FIFO (named pipe), not a regular file" 200000 -- \
    "$BIN/glsdis" "$t/fifo"
expect bundle_fifo_search_root 1 "glsc: error: search root $t/fifo: cannot read: it is a FIFO (named pipe), not a regular file" 200000 -- \
    "$BIN/glsc" -I "$t/fifo" -I tests/compiler/lang -o "$t/out.glsb" pkg.Leaf
expect bundle_directory 1 "glsplay: error: $t/dir: is a directory, not a bundle" 200000 -- \
    "$BIN/glsplay" "$t/dir" --camera "$CAM" --explain
expect bundle_device 1 "glsplay: error: /dev/zero: cannot read: it is a character device, not a regular file" 200000 -- \
    "$BIN/glsplay" /dev/zero --camera "$CAM" --explain
# 5 GiB of zeros (a sparse file): refused on its first 48 bytes
truncate -s 5G "$t/zeros.glsb"
expect bundle_large_not_a_bundle 1 "glsplay: error: $t/zeros.glsb: not a glscene bundle (bad magic number)" 200000 -- \
    "$BIN/glsplay" "$t/zeros.glsb" --camera "$CAM" --explain
# a real header declaring 5 GiB, in a file of that size
cp "$t/leaf.glsb" "$t/huge.glsb"
/usr/bin/python3 -c 'import struct, sys; f = open(sys.argv[1], "r+b"); f.seek(32); f.write(struct.pack("<Q", 5 << 30))' "$t/huge.glsb"
truncate -s 5G "$t/huge.glsb"
expect bundle_declared_over_limit 1 "glsplay: error: $t/huge.glsb: bundle of 5368709120 bytes: bundles must be smaller than 4294967296 bytes (4 GiB)" 200000 -- \
    "$BIN/glsplay" "$t/huge.glsb" --camera "$CAM" --explain
# a header declaring more than the file holds: the path once in the message
head -c 300 "$t/leaf.glsb" >"$t/short.glsb"
size=$(wc -c <"$t/leaf.glsb")
expect bundle_truncated_path_once 1 "glsplay: error: $t/short.glsb: bundle is truncated: header says $size bytes, only 300 present" 200000 -- \
    "$BIN/glsplay" "$t/short.glsb" --camera "$CAM" --explain
rm -f "$t/zeros.glsb" "$t/huge.glsb"
