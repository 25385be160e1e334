#!/bin/sh
# Occlusion culling (spec/bundle.md 9.3, "Occlusion culling"), not timed: with
# --occlusion on every file glsplay writes is byte-identical to
# --occlusion off, for a scene that hides most of its boxes behind
# alpha-tested trees (their holes must stay holes in the occluders) and
# over a road with coplanar markings, in a plain pass, the one-pass
# lattice (mapped fine tiles), jittered grid passes (a mosaic) and
# stratified passes, and for the lit example with shadows; --explain
# states the plan in each mode.  tests/unit/test_occlusion.c checks that
# the culling really skips items and the boxes' margin.  Prints
# "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
need_players occlusion

mkdir "$t/s"
cat >"$t/s/Occl.scene" <<'SCENE'
call("demo.Ground");
call("demo.Road");
repeat(i, 0, 16) { repeat(j, 0, 16) {
  push; trans(1.6 * i - 12, 0, 12 + 2 * j); rot(7 * i + 13 * j, 0, 1, 0); call("demo.BoxRed"); pop;
} }
repeat(i, 0, 9) { push; trans(1.8 * i - 8, 0, 7); scale(1.4); call("demo.Tree"); pop; }
SCENE
CAM=examples/demo/left.cam
"$B/glsc" -I "$t/s" -I examples/demo -I "$B/textures" -o "$t/o.glsb" "$t/s/Occl.scene" ||
    { fail occlusion "scene does not compile"; exit 0; }

# same NAME BUNDLE CAMERA OUTPUTS OPTIONS...: on and off write the same bytes
same() {
    name=$1 bundle=$2 cam=$3 outs=$4
    shift 4
    rm -rf "$t/on" "$t/off"
    if ! "$B/glsplay" "$bundle" --camera "$cam" --outputs "$outs" "$@" --occlusion on -o "$t/on" 2>"$t/err" ||
        ! "$B/glsplay" "$bundle" --camera "$cam" --outputs "$outs" "$@" --occlusion off -o "$t/off" 2>>"$t/err"; then
        fail "$name" "glsplay failed: $(head -c 300 "$t/err")"
        return
    fi
    n=0 bad=""
    for f in $(cd "$t/off" && find . -type f | sort); do
        n=$((n + 1))
        cmp -s "$t/on/$f" "$t/off/$f" || bad="$bad $f"
    done
    if [ "$n" -lt 2 ]; then
        fail "$name" "only $n files written"
    elif [ -n "$bad" ]; then
        fail "$name" "differ with --occlusion on:$bad"
    else
        ok "$name"
    fi
}
# --aa 1 where no samples are asked: exact coverage (the default) draws the
# image on the CPU, which occlusion culling, a GL pass's, does not touch
same occlusion_plain "$t/o.glsb" "$CAM" image,depth,instance,normals --aa 1
same occlusion_lattice "$t/o.glsb" "$CAM" image,depth --samples 16
same occlusion_grid_mosaic "$t/o.glsb" "$CAM" image --aa 3 --pattern grid
same occlusion_stratified "$t/o.glsb" "$CAM" image --aa 2 --pattern stratified

if "$B/glsc" -I "$B/scenelib.glsb" -o "$t/lit.glsb" examples/lighting/Lighting.scene 2>"$t/err"; then
    same occlusion_lit "$t/lit.glsb" examples/lighting/left.cam image,depth --aa 1
else
    fail occlusion_lit "the lighting example does not compile: $(head -c 300 "$t/err")"
fi

# --explain: the plan in each mode
"$B/glsplay" "$t/o.glsb" --camera "$CAM" --occlusion on --explain >"$t/on.txt" 2>&1
"$B/glsplay" "$t/o.glsb" --camera "$CAM" --occlusion off --explain >"$t/off.txt" 2>&1
"$B/glsc" -I examples/demo -I "$B/textures" -o "$t/demo.glsb" examples/demo/Demo.scene &&
    "$B/glsplay" "$t/demo.glsb" --camera "$CAM" --explain >"$t/auto.txt" 2>&1
if grep -q '^    occlusion culling: [0-9]* units tested in occlusion queries ([0-9]* triangles of their test boxes'"'"' front faces), nearest first, after [0-9]* draw items drawn untested (boxes over the image [0-9.]* times, the geometry [0-9.]* by the model)$' "$t/on.txt" &&
    grep -qx '    occlusion culling: off (--occlusion off)' "$t/off.txt" &&
    grep -q '^    occlusion culling: not used (auto, too little to gain; boxes over the image [0-9.]* times, the geometry [0-9.]* by the model, [0-9]* boxes, [0-9]* vertices; auto needs 4, 2, 256 and 200000)$' "$t/auto.txt"; then
    ok occlusion_explain
else
    fail occlusion_explain "$(grep 'occlusion' "$t/on.txt" "$t/off.txt" "$t/auto.txt" | head -c 600)"
fi
if "$B/glsplay" "$t/o.glsb" --camera "$CAM" --occlusion sometimes --explain >/dev/null 2>"$t/err"; then
    fail occlusion_usage "--occlusion sometimes accepted"
else
    rc=$?
    if [ "$rc" -eq 2 ] && grep -qx "glsplay: error: --occlusion takes one of: auto, on, off (not 'sometimes') (try glsplay --help)" "$t/err"; then
        ok occlusion_usage
    else
        fail occlusion_usage "exit $rc: $(head -c 300 "$t/err")"
    fi
fi
