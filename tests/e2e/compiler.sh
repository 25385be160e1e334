#!/bin/sh
# End-to-end tests of glsc and glsdis.  Prints "ok NAME" / "FAIL NAME".
. tests/e2e/lib.sh
BIN=$(cd "$B" && pwd)
ROOT=$(pwd)
tmp=$t

# Every construct, checked in the dump against a reviewed golden file.
if "$BIN/glsc" -I tests/compiler/lang -o "$tmp/lang.glsb" tests/compiler/lang/Top.scene &&
    "$BIN/glsdis" "$tmp/lang.glsb" >"$tmp/lang.dis" && cmp -s "$tmp/lang.dis" tests/compiler/all_constructs.dis; then
    ok compile_all_constructs
else
    fail compile_all_constructs "dump differs from tests/compiler/all_constructs.dis"
    diff tests/compiler/all_constructs.dis "$tmp/lang.dis" | head -20 | sed 's/^/    /'
fi
if "$BIN/glsdis" --source "$tmp/lang.glsb" >"$tmp/src.dis" && cmp -s "$tmp/src.dis" tests/compiler/all_constructs_source.dis; then
    ok dump_with_source_lines
else
    fail dump_with_source_lines "differs from tests/compiler/all_constructs_source.dis"
fi

# The paper's Figure 7, as it stands.
if "$BIN/glsc" -I tests/compiler/paper -o "$tmp/fig7.glsb" tests/compiler/paper/Figure7.scene 2>"$tmp/err" &&
    "$BIN/glsdis" "$tmp/fig7.glsb" | grep -q '^  call road.tex.vegetation.Tree2$'; then
    ok paper_figure7_compiles
else
    fail paper_figure7_compiles "$(head -3 "$tmp/err")"
fi

# The top can be named by dotted name, found through GLSCENE_PATH, and the
# default output is the last name component + .glsb, in the current directory.
(cd "$tmp" && GLSCENE_PATH="$ROOT/tests/compiler/paper" "$BIN/glsc" road.tex.roads.Curve400m) 2>"$tmp/err"
if [ -f "$tmp/Curve400m.glsb" ] && "$BIN/glsdis" "$tmp/Curve400m.glsb" | grep -q '^top: road.tex.roads.Curve400m$'; then
    ok top_by_dotted_name_via_GLSCENE_PATH
else
    fail top_by_dotted_name_via_GLSCENE_PATH "$(cat "$tmp/err")"
fi

# Only what the top reaches goes into the bundle.  (pkg.Leaf, a callee
# that leaves the texture mode to its caller, gets the "never applied"
# warning when it is compiled as the top.)
if "$BIN/glsc" -I tests/compiler/lang -o "$tmp/leaf.glsb" pkg.Leaf 2>"$tmp/err" && "$BIN/glsdis" "$tmp/leaf.glsb" | grep -q '^objects: 1, textures: 1,'; then
    ok bundle_holds_only_reachable_objects
else
    fail bundle_holds_only_reachable_objects "pkg.Leaf bundle has other objects"
fi

# A 24-bit TGA (BGR, no alpha) is a texture: opaque, channels in RGB order
# (four red texels: the CRC of ff0000ff x 4).
if "$BIN/glsc" -I tests/compiler/tga_rgb -o "$tmp/rgb.glsb" tests/compiler/tga_rgb/Top.scene 2>"$tmp/err" &&
    "$BIN/glsdis" "$tmp/rgb.glsb" | grep -qx 'texture tex.Rgb 2x2 rgba8 crc32=bc5aab1c'; then
    ok tga_rgb_texture
else
    fail tga_rgb_texture "$(head -1 "$tmp/err")"
fi

# Determinism: same sources twice; and a library tree whose files were
# created in the opposite order (different directory listing order).
"$BIN/glsc" -I tests/compiler/lang -o "$tmp/lang2.glsb" tests/compiler/lang/Top.scene
if cmp -s "$tmp/lang.glsb" "$tmp/lang2.glsb"; then ok deterministic_same_input; else fail deterministic_same_input "bundles differ"; fi
mkdir -p "$tmp/a" "$tmp/b"
for f in $(cd tests/compiler/paper && find . -type f | sort); do mkdir -p "$tmp/a/lib/$(dirname "$f")"; cp "tests/compiler/paper/$f" "$tmp/a/lib/$f"; done
for f in $(cd tests/compiler/paper && find . -type f | sort -r); do mkdir -p "$tmp/b/lib/$(dirname "$f")"; cp "tests/compiler/paper/$f" "$tmp/b/lib/$f"; done
(cd "$tmp/a" && "$BIN/glsc" --lib lib -o lib.glsb) && (cd "$tmp/b" && sleep 1 && TZ=Asia/Tokyo "$BIN/glsc" --lib lib -o lib.glsb)
if cmp -s "$tmp/a/lib.glsb" "$tmp/b/lib.glsb"; then ok deterministic_listing_order_and_time; else fail deterministic_listing_order_and_time "library bundles differ"; fi

# A library bundle stands in a search path exactly like its directory tree.
"$BIN/glsc" --lib tests/compiler/paper -o "$tmp/paper.glsb" 2>"$tmp/err"
"$BIN/glsdis" "$tmp/paper.glsb" | grep -q '^top: none (library bundle)$' || fail library_bundle_has_no_top "$(cat "$tmp/err")"
"$BIN/glsc" -I tests/compiler/paper -o "$tmp/viadir.glsb" tests/compiler/paper/Figure7.scene
cp tests/compiler/paper/Figure7.scene "$tmp/Figure7.scene"
"$BIN/glsc" -I "$tmp/paper.glsb" -o "$tmp/vialib.glsb" "$tmp/Figure7.scene" 2>"$tmp/err"
if "$BIN/glsdis" "$tmp/viadir.glsb" >"$tmp/d1" && "$BIN/glsdis" "$tmp/vialib.glsb" >"$tmp/d2" && cmp -s "$tmp/d1" "$tmp/d2"; then
    ok library_bundle_links_like_directory
else
    fail library_bundle_links_like_directory "$(cat "$tmp/err"; diff "$tmp/d1" "$tmp/d2" | head -5)"
fi

# Parameterised objects through a library bundle (spec/bundle.md 7.7): its
# templates keep their source, so values no object of the library has are
# made as from the directory, the same bundle byte for byte; values it has
# (pkg.Sized(size=2), which Top calls) are imported.
"$BIN/glsc" --lib tests/compiler/lang -o "$tmp/langlib.glsb" 2>"$tmp/err"
printf 'call("pkg.Sized", size = 3);\ncall("pkg.Sized", size = 2);\ncall("pkg.Sized");\n' >"$tmp/Sizes.scene"
"$BIN/glsc" -I tests/compiler/lang -o "$tmp/sizes_dir.glsb" "$tmp/Sizes.scene" 2>>"$tmp/err"
"$BIN/glsc" -I "$tmp/langlib.glsb" -o "$tmp/sizes_lib.glsb" "$tmp/Sizes.scene" 2>>"$tmp/err"
"$BIN/glsdis" "$tmp/langlib.glsb" >"$tmp/langlib.dis" 2>>"$tmp/err"
"$BIN/glsdis" "$tmp/sizes_lib.glsb" >"$tmp/sizes_lib.dis" 2>>"$tmp/err"
if cmp -s "$tmp/sizes_dir.glsb" "$tmp/sizes_lib.glsb" && grep -q '^template pkg.Sized(size=1) text ' "$tmp/langlib.dis" &&
    grep -q '^object pkg.Sized(size=2)$' "$tmp/langlib.dis" && ! grep -q 'size=3' "$tmp/langlib.dis" &&
    grep -qx 'object pkg.Sized(size=3)' "$tmp/sizes_lib.dis" && grep -qx '    vert 3 0 0' "$tmp/sizes_lib.dis"; then
    ok parameterised_library_links_like_directory
else
    fail parameterised_library_links_like_directory "$(head -3 "$tmp/err")"
fi

# Numbers print so that they round-trip: dump -> scene -> dump is a fixed point.
cat >"$tmp/Num.scene" <<'SCENE'
poly { vert(0.1, 1/3, -2/3); vert(1e-300, 123456789.123456789, 6.02214076e23); vert(10000000.001, -0.0, 2.5e-5); vert(1e16, 9007199254740993, 0.30000000000000004); }
SCENE
"$BIN/glsc" -I "$tmp" -o "$tmp/num.glsb" Num && "$BIN/glsdis" "$tmp/num.glsb" >"$tmp/num.dis"
{ echo 'poly {'; sed -n 's/^    vert \(.*\)$/\1/p' "$tmp/num.dis" | sed 's/ /, /g; s/^/vert(/; s/$/);/'; echo '}'; } >"$tmp/Num2.scene"
"$BIN/glsc" -I "$tmp" -o "$tmp/num2.glsb" Num2 && "$BIN/glsdis" "$tmp/num2.glsb" | sed 's/^top: Num2$/top: Num/; s/^object Num2$/object Num/' >"$tmp/num2.dis"
if cmp -s "$tmp/num.dis" "$tmp/num2.dis" && grep -q '^    vert 0.1 0.3333333333333333 -0.6666666666666666$' "$tmp/num.dis"; then
    ok numbers_round_trip_through_dump
else
    fail numbers_round_trip_through_dump "$(diff "$tmp/num.dis" "$tmp/num2.dis" | head -5)"
fi

# Corrupted and truncated bundles are refused with a message saying so.
size=$(wc -c <"$tmp/lang.glsb")
head -c $((size - 7)) "$tmp/lang.glsb" >"$tmp/trunc.glsb"
"$BIN/glsdis" "$tmp/trunc.glsb" >/dev/null 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'truncated' "$tmp/err"; then ok truncated_bundle_refused; else fail truncated_bundle_refused "rc=$rc $(cat "$tmp/err")"; fi
cp "$tmp/lang.glsb" "$tmp/bad.glsb"
printf '\377' | dd of="$tmp/bad.glsb" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
"$BIN/glsdis" "$tmp/bad.glsb" >/dev/null 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'corrupted' "$tmp/err"; then ok corrupted_bundle_refused; else fail corrupted_bundle_refused "rc=$rc $(cat "$tmp/err")"; fi

# Usage errors exit 2; --help exits 0.
"$BIN/glsc" >/dev/null 2>&1; r1=$?
"$BIN/glsc" --bogus x >/dev/null 2>&1; r2=$?
"$BIN/glsdis" >/dev/null 2>&1; r3=$?
"$BIN/glsc" --help >/dev/null 2>&1; r4=$?
if [ $r1 -eq 2 ] && [ $r2 -eq 2 ] && [ $r3 -eq 2 ] && [ $r4 -eq 0 ]; then ok usage_exit_status; else fail usage_exit_status "$r1 $r2 $r3 $r4"; fi
# The usage errors' first lines, verbatim (base/usage.c prints them; the
# usage text follows on the next lines).
usage_line() { # NAME EXPECTED_FIRST_LINE TOOL ARGS...
    name=$1 want=$2
    shift 2
    "$BIN/$@" >/dev/null 2>"$tmp/err"; rc=$?
    if [ $rc -eq 2 ] && [ "$(head -1 "$tmp/err")" = "$want" ] && grep -q "^usage: $1 " "$tmp/err"; then ok "$name"
    else fail "$name" "rc=$rc $(head -2 "$tmp/err")"; fi
}
usage_line usage_glsc_unknown_option "glsc: error: unknown option --bogus" glsc --bogus x
usage_line usage_glsc_missing_argument "glsc: error: missing argument after -I" glsc -I
usage_line usage_glsdis_no_bundle "glsdis: error: no bundle given" glsdis
usage_line usage_glsdis_unknown_option "glsdis: error: unknown option -x" glsdis -x
usage_line usage_glsdis_two_bundles "glsdis: error: more than one bundle given" glsdis a b
# an empty path names nothing: a usage error (spec/exit_status.md), where it
# was an input error (1) after trying to open it
usage_line usage_glsc_empty_output "glsc: error: empty argument after -o" glsc -o "" x.scene
usage_line usage_glsc_empty_root "glsc: error: empty argument after -I" glsc -I "" x.scene
usage_line usage_glsc_empty_lib "glsc: error: empty argument after --lib" glsc --lib "" -o x.glsb
usage_line usage_glsc_empty_top "glsc: error: an empty top-level object name" glsc ""
usage_line usage_glsdis_empty_bundle "glsdis: error: an empty bundle name" glsdis ""

# -o creates the directories it needs, as glsplay -o does.
if "$BIN/glsc" -I tests/compiler/paper -o "$tmp/new/sub/x.glsb" road.tex.roads.Curve400m 2>"$tmp/err" &&
    [ -s "$tmp/new/sub/x.glsb" ]; then
    ok output_directories_created
else
    fail output_directories_created "$(head -1 "$tmp/err")"
fi

# An unwritable output (a parent is a file) leaves nothing behind and exits 1.
: >"$tmp/afile"
"$BIN/glsc" -I tests/compiler/paper -o "$tmp/afile/x.glsb" road.tex.roads.Curve400m 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$tmp/err")" = "glsc: error: cannot create the directory of $tmp/afile/x.glsb: Not a directory" ] &&
    [ -f "$tmp/afile" ] && [ ! -s "$tmp/afile" ]; then
    ok unwritable_output
else
    fail unwritable_output "rc=$rc $(head -1 "$tmp/err")"
fi

# An existing output that is not a regular file is refused, never opened:
# writing into a FIFO nobody reads would block (timeout: a regression must
# not hang the suite), renaming over it would replace it.
mkfifo "$tmp/fifo.glsb"
timeout 20 "$BIN/glsc" -I tests/compiler/paper -o "$tmp/fifo.glsb" road.tex.roads.Curve400m 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && [ -p "$tmp/fifo.glsb" ] &&
    [ "$(cat "$tmp/err")" = "glsc: error: cannot write $tmp/fifo.glsb: it is a FIFO (named pipe), not a regular file" ] &&
    ! ls "$tmp"/fifo.glsb.tmp* >/dev/null 2>&1; then
    ok output_fifo_refused
else
    fail output_fifo_refused "rc=$rc $(head -1 "$tmp/err")"
fi
rm -f "$tmp/fifo.glsb"
mkdir "$tmp/outdir.glsb"
timeout 20 "$BIN/glsc" -I tests/compiler/paper -o "$tmp/outdir.glsb" road.tex.roads.Curve400m 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$tmp/err")" = "glsc: error: cannot write $tmp/outdir.glsb: it is a directory" ]; then
    ok output_directory_refused
else
    fail output_directory_refused "rc=$rc $(head -1 "$tmp/err")"
fi

# -o - writes the bundle to standard output, and no file named "-": the
# same bytes as -o FILE; a failed compile writes no byte of it; a failed
# write says why (the bundle is written past stdout's buffer)
mkdir "$tmp/cwd"
here=$(pwd)
# (the same directory and root: a bundle records its source paths)
(cd "$tmp/cwd" && "$BIN/glsc" -I "$here/tests/compiler/paper" -o "$tmp/curve.glsb" road.tex.roads.Curve400m)
(cd "$tmp/cwd" && "$BIN/glsc" -I "$here/tests/compiler/paper" -o - road.tex.roads.Curve400m) \
    >"$tmp/stdout.glsb" 2>"$tmp/err"; rc=$?
if [ $rc -eq 0 ] && [ -s "$tmp/curve.glsb" ] && cmp -s "$tmp/curve.glsb" "$tmp/stdout.glsb" &&
    [ -z "$(ls -A "$tmp/cwd")" ] && [ ! -s "$tmp/err" ]; then
    ok output_stdout
else
    fail output_stdout "rc=$rc $(head -1 "$tmp/err"); in the directory: $(ls -A "$tmp/cwd")"
fi
(cd "$tmp/cwd" && "$BIN/glsc" -I "$here/tests/compiler/paper" -o - road.tex.roads.NoSuch) >"$tmp/stdout.glsb" \
    2>"$tmp/err"; rc=$?
[ $rc -eq 1 ] && [ ! -s "$tmp/stdout.glsb" ] && [ -z "$(ls -A "$tmp/cwd")" ] && ok output_stdout_nothing_on_error ||
    fail output_stdout_nothing_on_error "rc=$rc, $(wc -c <"$tmp/stdout.glsb") bytes on stdout"
(cd "$tmp/cwd" && "$BIN/glsc" --lib "$here/tests/compiler/paper" -o -) >"$tmp/lib.glsb" 2>"$tmp/err" &&
    "$BIN/glsdis" "$tmp/lib.glsb" >/dev/null && [ -z "$(ls -A "$tmp/cwd")" ] && ok output_stdout_lib || fail output_stdout_lib "$(head -1 "$tmp/err")"
if [ -c /dev/full ]; then
    (cd "$tmp/cwd" && "$BIN/glsc" -I "$here/tests/compiler/paper" -o - road.tex.roads.Curve400m) >/dev/full \
        2>"$tmp/err"; rc=$?
    [ $rc -eq 1 ] && [ "$(cat "$tmp/err")" = "glsc: error: cannot write standard output: No space left on device" ] &&
        ok output_stdout_full || fail output_stdout_full "rc=$rc $(cat "$tmp/err")"
fi

# Call depth: 256 nested calls compile; 257 do not, also when the long
# chain runs through an object that an earlier, shorter chain already reached.
mkdir -p "$tmp/deep"
i=0
while [ $i -lt 257 ]; do echo "call(\"C$((i + 1))\");" >"$tmp/deep/C$i.scene"; i=$((i + 1)); done
echo 'color(1, 0, 0);' >"$tmp/deep/C257.scene"
if "$BIN/glsc" -I "$tmp/deep" -o "$tmp/deep.glsb" C1 2>"$tmp/err"; then ok call_depth_256_allowed; else fail call_depth_256_allowed "$(head -1 "$tmp/err")"; fi
"$BIN/glsc" -I "$tmp/deep" -o "$tmp/deep0.glsb" C0 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'calls nest more than 256 deep' "$tmp/err" && [ ! -e "$tmp/deep0.glsb" ]; then
    ok call_depth_257_refused
else
    fail call_depth_257_refused "rc=$rc $(head -1 "$tmp/err")"
fi
printf 'call("C100");\ncall("Via");\n' >"$tmp/deep/Top.scene"
i=0; prev=C100
while [ $i -lt 100 ]; do echo "call(\"$prev\");" >"$tmp/deep/V$i.scene"; prev=V$i; i=$((i + 1)); done
echo "call(\"$prev\");" >"$tmp/deep/Via.scene"
"$BIN/glsc" -I "$tmp/deep" -o "$tmp/top.glsb" Top 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'calls nest more than 256 deep' "$tmp/err" && [ "$(grep -c error: "$tmp/err")" -eq 1 ]; then
    ok call_depth_through_visited_object
else
    fail call_depth_through_visited_object "rc=$rc $(head -3 "$tmp/err")"
fi

# A library file whose name is not an identifier is refused, not misnamed.
mkdir -p "$tmp/dotlib"
echo 'color(1, 0, 0);' >"$tmp/dotlib/a.b.scene"
"$BIN/glsc" --lib "$tmp/dotlib" -o "$tmp/dot.glsb" 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'a.b.scene: a file name must be an identifier before its extension' "$tmp/err"; then
    ok library_refuses_dotted_file_name
else
    fail library_refuses_dotted_file_name "rc=$rc $(cat "$tmp/err")"
fi

# A stale GLSCENE_PATH entry is a warning, not an error.
GLSCENE_PATH="/no/such/dir:$ROOT/tests/compiler/paper" "$BIN/glsc" -o "$tmp/w.glsb" road.tex.roads.Curve400m 2>"$tmp/err"; rc=$?
if [ $rc -eq 0 ] && grep -q 'warning: GLSCENE_PATH entry /no/such/dir does not exist; ignored' "$tmp/err"; then
    ok stale_GLSCENE_PATH_entry_ignored
else
    fail stale_GLSCENE_PATH_entry_ignored "rc=$rc $(cat "$tmp/err")"
fi

# A call DAG that unrolls to an exponential number of call paths (each
# level calls the next twice: 2^31 - 1 paths, 2^30 triangles, from 31 small
# files) is refused at compile time, before any player would try to draw it.
mkdir -p "$tmp/bomb"
i=0
while [ $i -lt 30 ]; do printf 'call("B%d");\ncall("B%d");\n' $((i + 1)) $((i + 1)) >"$tmp/bomb/B$i.scene"; i=$((i + 1)); done
echo 'tfan { vert(0); vert(1); vert(2); }' >"$tmp/bomb/B30.scene"
"$BIN/glsc" -I "$tmp/bomb" -o "$tmp/bomb.glsb" B0 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && [ "$(cat "$tmp/err")" = "glsc: error: B0 has more than 4194304 call paths (instances to draw) once its calls are unrolled: too many to render" ]; then
    ok call_expansion_bomb_refused
else
    fail call_expansion_bomb_refused "rc=$rc $(head -2 "$tmp/err")"
fi

# An input over the size limit (1 GiB) is refused from its size, before any
# of it is read: a sparse file costs no disk.
truncate -s 1100M "$tmp/Huge.scene"
"$BIN/glsc" -I "$tmp" -o "$tmp/huge.glsb" Huge 2>"$tmp/err"; rc=$?
if [ $rc -eq 1 ] && grep -q 'Huge.scene is 1153433600 bytes, more than the limit of 1073741824' "$tmp/err"; then
    ok source_size_limit
else
    fail source_size_limit "rc=$rc $(head -2 "$tmp/err")"
fi
rm -f "$tmp/Huge.scene"
