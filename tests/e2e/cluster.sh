#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# Sequences spread over processes (spec/road.md "Sharding"): glsplay
# --shard I/N and --shard slurm, their usage errors (verbatim), GNU
# Parallel for real (the union of 3 shards == one unsharded render, every
# file byte for byte), an interrupted shard that resumes to the same
# bytes, docs/cluster/slurm.sh run with SLURM_* variables set (not under
# Slurm), and --progress json parsed line by line.  Prints ok/FAIL lines.
. tests/e2e/lib.sh
tmp=$t

# the road demo: scene, trajectory, motion files
"$BIN/glsroad" examples/road/demo.road -o "$tmp/road" >/dev/null 2>&1 &&
    "$BIN/glsc" -I "$tmp/road" -I "$BIN/scenelib.glsb" -o "$tmp/road.glsb" "$tmp/road/road.scene" ||
    { fail cluster_setup "the road demo does not build"; exit 0; }
GLSPLAY=$(cd "$BIN" && pwd)/glsplay
# the demo's sequence command (docs/roads.md), frames 3..11 written with every
# output and the calibration files; at one sample a pixel (--aa 1): the
# sharding is under test, not the anti-aliasing, and exact coverage (the
# default) would draw these 18 road frames on the CPU three times over
set -- "$tmp/road.glsb" --camera examples/road/rig/left.cam --camera examples/road/rig/right.cam \
    --trajectory "$tmp/road/trajectory.txt" --frames 3:12 --background 0.55,0.7,0.9 --aa 1 \
    --motion lead="$tmp/road/motion/lead.txt" --motion oncoming="$tmp/road/motion/oncoming.txt"
"$GLSPLAY" "$@" --write-calib -o "$tmp/whole" 2>"$tmp/err" || { fail cluster_setup "$(cat "$tmp/err")"; exit 0; }

# --- usage errors, verbatim (exit 2) ---
usage() { # NAME EXPECTED-LINE ARGS...: exit 2 and exactly that line
    name=$1 want=$2
    shift 2
    "$GLSPLAY" "$@" >"$tmp/uo" 2>"$tmp/ue"
    rc=$?
    if [ $rc -eq 2 ] && [ "$(cat "$tmp/ue")" = "$want" ] && [ ! -s "$tmp/uo" ]; then
        ok "$name"
    else
        fail "$name" "exit $rc: $(cat "$tmp/ue")"
    fi
}
B="$tmp/road.glsb"
usage shard_usage_range "glsplay: error: --shard needs I/N with 0 <= I < N (or slurm), got '3/3' (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard 3/3 -o "$tmp/u"
usage shard_usage_garbled "glsplay: error: --shard needs I/N with 0 <= I < N (or slurm), got '1of3' (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard 1of3 -o "$tmp/u"
usage shard_usage_missing "glsplay: error: --shard needs I/N with 0 <= I < N (or slurm) (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard
usage shard_slurm_unset "glsplay: error: --shard slurm: SLURM_ARRAY_TASK_ID is not set (run glsplay as a task of a Slurm job array, sbatch --array, or give --shard I/N) (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard slurm -o "$tmp/u"
export SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=three
usage shard_slurm_garbled "glsplay: error: --shard slurm: SLURM_ARRAY_TASK_COUNT is 'three', not a whole number (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard slurm -o "$tmp/u"
export SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1
usage shard_slurm_not_array "glsplay: error: --shard slurm: SLURM_ARRAY_TASK_ID 7 is not task 0..2 of an array from SLURM_ARRAY_TASK_MIN 1 in steps of 1 (give --shard I/N for other arrays) (try glsplay --help)" \
    "$B" --camera examples/demo/left.cam --shard slurm -o "$tmp/u"
unset SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_COUNT SLURM_ARRAY_TASK_MIN
[ -e "$tmp/u" ] && fail shard_usage_writes_nothing "a usage error created $tmp/u" || ok shard_usage_writes_nothing

# --- --explain: the shard and its frame count ---
"$GLSPLAY" "$@" --shard 1/3 --explain >"$tmp/plan" 2>"$tmp/err"
if grep -qx 'shard 1/3: the frames f with (f - 3) mod 3 = 1: 3 of the 9 frames in range' "$tmp/plan"; then
    ok shard_explain
else
    fail shard_explain "$(grep shard "$tmp/plan"; cat "$tmp/err")"
fi

# --- one shard alone: exactly its frames, and the run-wide calibration ---
"$GLSPLAY" "$@" --write-calib --shard 2/3 -o "$tmp/one" 2>"$tmp/err"
got=$(cd "$tmp/one" && find . -type f | sort | tr '\n' ' ')
want=$(cd "$tmp/whole" && find . -type f | grep -E '_0000(05|08|11)\.|calib\.txt|camera_info' | sort | tr '\n' ' ')
if [ "$got" = "$want" ]; then
    ok shard_renders_its_frames
else
    fail shard_renders_its_frames "got: $got; want: $want"
fi

# --- GNU Parallel: 3 shards, 2 at a time, into one directory ---
if ! command -v parallel >/dev/null; then
    fail parallel_union "GNU parallel is not installed (tools/deps.sh installs it)"
else
    parallel --will-cite -j2 --halt now,fail=1 "$GLSPLAY" "$@" --write-calib --shard {}/3 -o "$tmp/par" ::: 0 1 2 2>"$tmp/err"
    rc=$?
    if [ $rc -eq 0 ] && diff -r "$tmp/whole" "$tmp/par" >"$tmp/diff" 2>&1 &&
        [ "$(find "$tmp/par" -type f | wc -l)" -eq "$(find "$tmp/whole" -type f | wc -l)" ]; then
        ok parallel_union_equals_unsharded
    else
        fail parallel_union_equals_unsharded "parallel exit $rc; $(head -5 "$tmp/diff"; head -5 "$tmp/err")"
    fi
fi

# --- a shard killed after its first frame resumes to the same bytes ---
# slow enough (64 samples a pixel) that it is still rendering when
# killed; its frames 4, 7, ..., 19 of 3:21
set -- "$tmp/road.glsb" --camera examples/road/rig/left.cam --trajectory "$tmp/road/trajectory.txt" \
    --frames 3:21 --samples 64 --outputs image,depth --shard 1/3
"$GLSPLAY" "$@" -o "$tmp/ref" 2>"$tmp/err" || fail shard_resume_setup "$(cat "$tmp/err")"
mkfifo "$tmp/fifo"
"$GLSPLAY" "$@" --progress json -o "$tmp/killed" 2>"$tmp/fifo" &
pid=$!
first=""
while IFS= read -r line; do
    case $line in
    *'"event": "frame"'*) first=$line; kill -KILL $pid; break ;;
    esac
done <"$tmp/fifo"
{ wait $pid; } 2>/dev/null # no "Killed" from the shell
rc=$?
records=$(ls -A "$tmp/killed/left" 2>/dev/null | grep -c '^\.frame_.*\.done$')
if [ -z "$first" ] || [ $rc -ne 137 ] || [ "$records" -lt 1 ] || [ "$records" -ge 6 ]; then
    fail shard_killed "exit $rc after '$first': $records of 6 frames complete (want killed part way)"
else
    ok shard_killed
fi
"$GLSPLAY" "$@" --resume -o "$tmp/killed" 2>"$tmp/err"
rc=$?
# a write cut off by the kill may leave its temporary file (NAME.tmpPID)
if [ $rc -eq 0 ] && grep -q "^glsplay: note: --resume: $records of 6 frames complete, skipped; $((6 - records)) to render\$" "$tmp/err" &&
    diff -r -x "*.tmp$pid" "$tmp/ref" "$tmp/killed" >"$tmp/diff" 2>&1; then
    ok shard_resume_same_bytes
else
    fail shard_resume_same_bytes "exit $rc: $(cat "$tmp/err"; head -5 "$tmp/diff")"
fi

# --- docs/cluster/slurm.sh, run as the 3 tasks of an array --array=1-3 ---
if bash -n docs/cluster/slurm.sh; then ok slurm_script_syntax; else fail slurm_script_syntax "bash -n"; fi
for id in 1 2 3; do
    SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_COUNT=3 SLURM_ARRAY_TASK_MIN=1 GLSPLAY=$GLSPLAY BUNDLE=$tmp/road.glsb \
        TRAJECTORY=$tmp/road/trajectory.txt OUTDIR=$tmp/slurm FRAMES=3:12 \
        bash docs/cluster/slurm.sh --background 0.55,0.7,0.9 --aa 1 --write-calib \
        --motion lead="$tmp/road/motion/lead.txt" --motion oncoming="$tmp/road/motion/oncoming.txt" \
        2>>"$tmp/slurm.log" || echo "task $id failed" >>"$tmp/slurm.log"
done
if ! grep -q failed "$tmp/slurm.log" && diff -r "$tmp/whole" "$tmp/slurm" >"$tmp/diff" 2>&1; then
    ok slurm_script_union_equals_unsharded
else
    fail slurm_script_union_equals_unsharded "$(tail -5 "$tmp/slurm.log"; head -5 "$tmp/diff")"
fi

# --- --progress json: every stderr line is a JSON object, in order ---
# (the slurm tasks' logs above: a task line from the script, then glsplay's
# note of --resume, a line of its own, then its JSON lines)
grep -v '^glscene: task' "$tmp/slurm.log" >"$tmp/json.log"
if $PY - "$tmp/json.log" <<'PY' >"$tmp/pyerr" 2>&1; then ok progress_json_lines; else fail progress_json_lines "$(cat "$tmp/pyerr")"; fi
import json, sys
lines = open(sys.argv[1]).read().split("\n")
assert lines[-1] == "", "the stream ends without a newline"
tasks, cur = [], None
notes = 0
for ln in lines[:-1]:
    if ln == "glsplay: note: --resume: 0 of 3 frames complete, skipped; 3 to render":
        notes += 1
        continue
    o = json.loads(ln)  # every other line whole JSON, nothing else mixed in
    if o["event"] == "frame":
        if cur is None:
            cur = []
        cur.append(o)
    else:
        assert o["event"] == "end" and o["status"] == "ok", o
        tasks.append((cur or [], o))
        cur = None
assert cur is None and len(tasks) == 3 and notes == 3, (len(tasks), notes)
frames = []
for i, (fr, end) in enumerate(tasks):
    # shard i of frames 3..11: 3 + i, 6 + i, 9 + i, both cameras in turn
    want = [(f, c) for f in (3 + i, 6 + i, 9 + i) for c in ("left", "right")]
    assert [(o["frame"], o["camera"]) for o in fr] == want, fr
    assert [o["done"] for o in fr] == list(range(1, 7)) and all(o["total"] == 6 for o in fr), fr
    assert all(o["elapsed_s"] >= 0 and o["rate_fps"] > 0 and o["eta_s"] >= 0 for o in fr), fr
    assert fr[-1]["eta_s"] == 0, fr[-1]
    el = [o["elapsed_s"] for o in fr]
    assert el == sorted(el), el
    assert end["done"] == 6 and end["total"] == 6 and end["frames"] == 3 and end["skipped"] == 0, end
    frames += [o["frame"] for o in fr]
assert sorted(set(frames)) == list(range(3, 12)), frames
PY

# --progress json with --resume: the skipped frames counted, none said
"$GLSPLAY" "$tmp/road.glsb" --camera examples/road/rig/left.cam --trajectory "$tmp/road/trajectory.txt" \
    --frames 3:21 --samples 64 --outputs image,depth --shard 1/3 --resume --progress json -o "$tmp/ref" 2>"$tmp/err"
if [ "$(cat "$tmp/err")" = 'glsplay: note: --resume: 6 of 6 frames complete, skipped; 0 to render' ] ||
    [ "$(sed -n 2p "$tmp/err" | sed 's/"elapsed_s": [0-9.]*/E/')" != '{"event": "end", "status": "ok", "done": 0, "total": 0, "frames": 0, "skipped": 6, E, "rate_fps": 0.000}' ]; then
    fail progress_json_resume "$(cat "$tmp/err")"
else
    ok progress_json_resume
fi

# --- a single render: shard 0's; other shards write the run-wide files only ---
"$GLSPLAY" "$tmp/road.glsb" --camera examples/demo/left.cam --write-calib --shard 1/2 -o "$tmp/single1" 2>"$tmp/err"
rc=$?
"$GLSPLAY" "$tmp/road.glsb" --camera examples/demo/left.cam --write-calib --shard 0/2 -o "$tmp/single0" 2>/dev/null
if [ $rc -eq 0 ] &&
    [ "$(cat "$tmp/err")" = "glsplay: note: --shard 1/2: a single render (no --trajectory) is shard 0's; nothing to render" ] &&
    [ "$(cd "$tmp/single1" && find . -type f | sort | tr '\n' ' ')" = "./calib.txt ./left/camera_info.yaml " ] &&
    cmp -s "$tmp/single0/calib.txt" "$tmp/single1/calib.txt" &&
    cmp -s "$tmp/single0/left/camera_info.yaml" "$tmp/single1/left/camera_info.yaml" &&
    [ -f "$tmp/single0/left/image_000000.png" ]; then
    ok shard_single_render
else
    fail shard_single_render "exit $rc: $(cat "$tmp/err"; cd "$tmp/single1" && find . -type f)"
fi

# more shards than frames: a shard with none says so and succeeds
"$GLSPLAY" "$tmp/road.glsb" --camera examples/road/rig/left.cam --trajectory "$tmp/road/trajectory.txt" \
    --frames 3:5 --shard 2/3 -o "$tmp/empty" 2>"$tmp/err"
rc=$?
if [ $rc -eq 0 ] &&
    [ "$(cat "$tmp/err")" = "glsplay: note: --shard 2/3: none of the 2 frames in range is this shard's; nothing to render" ]; then
    ok shard_without_frames
else
    fail shard_without_frames "exit $rc: $(cat "$tmp/err")"
fi
