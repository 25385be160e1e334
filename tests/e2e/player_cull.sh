#!/bin/sh
# Frustum culling of instances (spec/bundle.md 9.3), not timed: a scene
# of instances in front of, behind, beside and beyond the camera, and one
# straddling the right edge of the view.  --explain's drawn and culled
# counts are asserted exactly for two cameras (one looking forward, one
# back), the straddling instance must be drawn (its pixels counted), and
# each image must equal --flatten's (which culls no instance) byte for
# byte, depth within the documented rounding.  Prints "ok NAME" /
# "FAIL NAME: why".
. tests/e2e/lib.sh
need_players player_cull

mkdir "$t/s"
cat >"$t/s/Tile.scene" <<'SCENE'
// a 1 x 1 square in z = 0, centred on the origin
poly { vert(-0.5, -0.5, 0); vert(0.5, -0.5, 0); vert(0.5, 0.5, 0); vert(-0.5, 0.5, 0); }
SCENE
# front.cam: at the origin looking along +z, 320x240, f 200: the view at
# z = 10 spans x -8..8, y -6..6.  back.cam: the same place looking along -z.
cat >"$t/s/Cull.scene" <<'SCENE'
color(1, 0, 0); repeat(i, -1, 2) { push; trans(2 * i, 0, 10); call("Tile"); pop; }  // 3 in front
color(0, 1, 0); repeat(i, -1, 1) { push; trans(2 * i, 0, -10); call("Tile"); pop; } // 2 behind
color(0, 0, 1); push; trans(-30, 0, 10); call("Tile"); pop;                           // beside, left
                push; trans(0, 30, 10); call("Tile"); pop;                            // beside, below
color(1, 1, 0); push; trans(0, 0, 500); call("Tile"); pop;                            // beyond far
color(1, 0, 1); push; trans(8, 3, 10); call("Tile"); pop;  // x 7.5..8.5: straddles the right edge
SCENE
cam() {
    printf 'width 320\nheight 240\nfx 200\nfy 200\ncx 159.5\ncy 119.5\nR %s\nT 0 0 0\nnear 0.1\nfar 100\n' "$2" >"$t/$1.cam"
}
cam front "1 0 0 0 1 0 0 0 1"
cam back "-1 0 0 0 1 0 0 0 -1"
"$B/glsc" -I "$t/s" -o "$t/cull.glsb" Cull || { fail player_cull "scene does not compile"; exit 0; }

# --explain: the exact counts per camera (instances with geometry: the 9
# calls; the top object draws nothing of its own)
"$B/glsplay" "$t/cull.glsb" --camera "$t/front.cam" --camera "$t/back.cam" --explain >"$t/explain" 2>&1
for want in "front 4 5 4" "back 2 7 2"; do
    set -- $want
    line="  camera $1, first frame: $2 instances drawn, $3 culled (outside the view); $4 of 9 items drawn"
    if grep -qxF "$line" "$t/explain"; then ok "cull_explain_$1"
    else fail "cull_explain_$1" "wanted '$line', got: $(grep "camera $1," "$t/explain")"; fi
done

# images: instanced against --flatten, and what each camera shows
"$B/glsplay" "$t/cull.glsb" --camera "$t/front.cam" --camera "$t/back.cam" -o "$t/inst" 2>"$t/err" &&
    "$B/glsplay" "$t/cull.glsb" --camera "$t/front.cam" --camera "$t/back.cam" --flatten -o "$t/flat" 2>>"$t/err" ||
    { fail player_cull "glsplay failed: $(cat "$t/err")"; exit 0; }
for c in front back; do
    if cmp -s "$t/inst/$c/image_000000.png" "$t/flat/$c/image_000000.png"; then ok "cull_image_equals_flatten_$c"
    else fail "cull_image_equals_flatten_$c" "the instanced image differs from --flatten's"; fi
done
[ -x $PY ] && $PY -c 'import cv2' 2>/dev/null || { fail player_cull_opencv "no OpenCV under $PY"; exit 0; }
$PY - "$t/inst" "$t/flat" <<'PYEOF'
import sys
import cv2
import numpy as np
sys.path.insert(0, "tests/py")
from examples_check import read_pfm

inst, flat = sys.argv[1], sys.argv[2]
def check(name, cond, why):
    print(("ok " if cond else "FAIL ") + name + ("" if cond else ": " + why))

# pixels of each colour (BGR): red 3 tiles of 20 x 20 px in front; the
# magenta tile covers u 309.5..320 (10 columns), v 169.5..189.5 (20 rows);
# green: the 2 tiles behind, seen by the back camera
want = {"front": {"red": 1200, "magenta": 200, "green": 0, "blue": 0, "yellow": 0},
        "back": {"red": 0, "magenta": 0, "green": 800, "blue": 0, "yellow": 0}}
bgr = {"red": (0, 0, 255), "green": (0, 255, 0), "blue": (255, 0, 0), "yellow": (0, 255, 255), "magenta": (255, 0, 255)}
for cam, counts in want.items():
    img = cv2.imread(f"{inst}/{cam}/image_000000.png").reshape(-1, 3)
    got = {k: int((img == bgr[k]).all(1).sum()) for k in counts}
    check(f"cull_pixels_{cam}", got == counts, f"pixels by colour {got}, wanted {counts}")
    # depth: the same coverage, values within spec/bundle.md 9.3's 2.4e-5
    a = read_pfm(f"{inst}/{cam}/depth_000000.pfm")
    b = read_pfm(f"{flat}/{cam}/depth_000000.pfm")
    fa, fb = np.isfinite(a) & (a > 0), np.isfinite(b) & (b > 0)
    rel = float(np.max(np.abs(a[fa] - b[fa]) / b[fa])) if fa.any() and (fa == fb).all() else 0.0
    check(f"cull_depth_equals_flatten_{cam}", (fa == fb).all() and fa.any() and rel <= 2.4e-5,
          f"coverage differs in {int((fa != fb).sum())} pixels, largest relative difference {rel:.3g}")
PYEOF
