#!/bin/sh
# --aa exact on the textured scenes (make bench-aa section 6): the demo
# (left camera, 640x480) and one frame of the road demo (frame 4, right
# camera, 640x480), whole glsplay process, best of REPS runs interleaved
# (each round runs every setting once, so that a swing of the shared
# machine's load falls on all of them), against one plain pass in the same
# run; and the per-pixel difference of one pass and of --aa exact from 256
# lattice samples (PFM, full scale 1).  Then the road sequence's worst
# frame: every STEP-th frame of its 500 (AA_EXACT_STEP, default 25), one
# frame a process, --aa exact against one plain pass, best of 3 each.
# Usage: sh bench/aa_exact_scenes.sh [BUILD [REPS]]; prints markdown.
B=${1:-build}
REPS=${2:-3}
. bench/lib.sh
fixed_malloc
work_dir
"$B/glsc" -I examples/demo -I "$B/textures" -o "$t/demo.glsb" examples/demo/Demo.scene 2>"$t/err" &&
    "$B/glsroad" examples/road/demo.road -o "$t/road" >/dev/null 2>>"$t/err" &&
    "$B/glsc" -I "$t/road" -I "$B/scenelib.glsb" -o "$t/road.glsb" "$t/road/road.scene" 2>>"$t/err" ||
    { cat "$t/err" >&2; exit 1; }
SETTINGS="--aa=1 --aa=exact --samples=16 --samples=256"
play() { # scene setting [more options]: one whole run
    sc=$1 opt=$(echo "$2" | tr = ' ')
    shift 2
    case $sc in
    demo) "$B/glsplay" "$t/demo.glsb" --camera examples/demo/left.cam --outputs image $opt "$@" ;;
    road) "$B/glsplay" "$t/road.glsb" --camera examples/road/rig/right.cam --trajectory "$t/road/trajectory.txt" \
        --frames 4:5 --outputs image $opt "$@" ;;
    esac
}
for sc in demo road; do
    r=0
    while [ $r -lt "$REPS" ]; do
        for s in $SETTINGS; do
            rm -rf "$t/o"
            t0=$(now)
            play $sc $s -o "$t/o" 2>"$t/err" || { cat "$t/err" >&2; exit 1; }
            echo "$sc $s $(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.3f", b - a }')" >>"$t/times"
        done
        r=$((r + 1))
    done
    for s in --aa=1 --aa=exact --samples=256; do
        play $sc $s --image-format pfm -o "$t/$sc$s" 2>"$t/err" || { cat "$t/err" >&2; exit 1; }
    done
done
echo "load average (1, 5, 15 min) after the runs: $(loadavg 3); $(machine)"
echo
echo "| scene | options | s (best of $REPS) | x one pass | max diff from 256 samples | mean diff |"
echo "|---|---|---|---|---|---|"
for sc in demo road; do
    one=$(awk -v sc=$sc '$1 == sc && $2 == "--aa=1" { if (b == "" || $3 < b) b = $3 } END { print b }' "$t/times")
    for s in $SETTINGS; do
        best=$(awk -v sc=$sc -v s="$s" '$1 == sc && $2 == s { if (b == "" || $3 < b) b = $3 } END { print b }' "$t/times")
        d="- | -"
        if [ -d "$t/$sc$s" ]; then
            d=$(/usr/bin/python3 - "$t" "$sc" "$s" <<'PYEOF'
import sys, glob, numpy as np
def pfm(p):
    with open(p, 'rb') as f:
        kind = f.readline().strip(); w, h = map(int, f.readline().split()); sc = float(f.readline())
        a = np.frombuffer(f.read(), '<f4' if sc < 0 else '>f4').reshape(h, w, 3 if kind == b'PF' else 1)
    return a.astype(np.float64)
t, sc, s = sys.argv[1:]
one = lambda k: pfm(glob.glob('%s/%s%s/*/image_*.pfm' % (t, sc, k))[0])
d = np.abs(one(s) - one('--samples=256'))
print('%.3g | %.3g' % (d.max(), d.mean()))
PYEOF
)
        fi
        printf '| %s | %s | %.3f | %.2f | %s |\n' $sc "$(echo "$s" | tr = ' ')" "$best" "$(echo "$best / $one" | bc -l)" "$d"
    done
done

# ---- the road sequence: the worst frame, not the one above --------------
STEP=${AA_EXACT_STEP:-25}
NF=$(grep -vc '^#' "$t/road/trajectory.txt")
: >"$t/seq"
f=0
while [ "$f" -lt "$NF" ]; do
    for r in 1 2 3; do
        for s in --aa=1 --aa=exact; do
            rm -rf "$t/o"
            t0=$(now)
            "$B/glsplay" "$t/road.glsb" --camera examples/road/rig/right.cam --trajectory "$t/road/trajectory.txt" \
                --frames "$f:$((f + 1))" --outputs image $(echo "$s" | tr = ' ') -o "$t/o" 2>"$t/err" ||
                { cat "$t/err" >&2; exit 1; }
            echo "$f $s $(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.3f", b - a }')" >>"$t/seq"
        done
    done
    f=$((f + STEP))
done
echo
echo "The road sequence (right camera, 640x480), every $STEP-th of its $NF frames, one frame a process, best of 3;"
echo "load average after: $(loadavg 3):"
echo
awk '{ k = $1 " " $2; if (!(k in b) || $3 < b[k]) b[k] = $3; fr[$1] = 1 }
END {
    n = 0
    for (f in fr) { r = b[f " --aa=exact"] / b[f " --aa=1"]; rs[n++] = r; if (r > w) { w = r; wf = f } }
    for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) if (rs[j] < rs[i]) { x = rs[i]; rs[i] = rs[j]; rs[j] = x }
    printf "| frames | --aa exact x one pass: median | worst | worst frame | its one pass s | its exact s |\n"
    printf "|---|---|---|---|---|---|\n"
    printf "| %d | %.2f | %.2f | %d | %.3f | %.3f |\n", n, rs[int((n - 1) / 2)], w, wf, b[wf " --aa=1"], b[wf " --aa=exact"]
}' "$t/seq"
