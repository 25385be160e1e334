"""The Python binding (python/glscene, README "Use it from Python") under
/usr/bin/python3, run by tests/e2e/python_binding.sh:
    check_python.py BUILD TMPDIR
Compiles a wall with a named tile in front of it, renders it through a
turned and moved camera and checks the depth against the camera model in
numpy; checks ids, a moved instance, the image against glsplay's PNG of
the demo (same camera, --aa, background), the depth against glsplay's
PFM, and that errors raise glscene.Error with the library's message;
that a camera by numbers (glscene_render) gives the arrays a file's
camera (a run of the player) gives, a rig a list of dicts with the
records' dtypes, scene text compiles, and the run's errors (an output word,
a camera's text, flow without a trajectory, a closed player, move() before
a run) come back as glscene.Error.
Prints "ok NAME" / "FAIL NAME: why"."""
import os
import subprocess
import sys

import cv2
import numpy as np

BUILD, TMP = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
os.environ["GLSCENE_LIBRARY"] = os.path.join(BUILD, "libglscene.so.0")
import glscene  # noqa: E402

import gt_checks  # noqa: E402

result = gt_checks.result

WALL = """// a wall at z = 10, a 1 x 1 tile named "mover" at z = 5
color(0.5, 0.5, 0.5);
poly { vert(-100, -100, 10); vert(100, -100, 10); vert(100, 100, 10); vert(-100, 100, 10); }
push; trans(0, 0, 5); call("parts.Tile", "mover"); pop;
"""
TILE = """color(1, 0, 0);
poly { vert(-0.5, -0.5, 0); vert(0.5, -0.5, 0); vert(0.5, 0.5, 0); vert(-0.5, 0.5, 0); }
"""
os.makedirs(os.path.join(TMP, "parts"), exist_ok=True)
with open(os.path.join(TMP, "Wall.scene"), "w") as f:
    f.write(WALL)
with open(os.path.join(TMP, "parts", "Tile.scene"), "w") as f:
    f.write(TILE)
bundle = os.path.join(TMP, "wall.glsb")
result("python_compile", glscene.compile("Wall", [TMP], bundle) == bundle and os.path.getsize(bundle) > 0)

# a camera turned 20 degrees about y and 10 about x, away from the origin
W, H = 160, 120
a, b = np.radians(20), np.radians(10)
Ry = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
Rx = np.array([[1, 0, 0], [0, np.cos(b), -np.sin(b)], [0, np.sin(b), np.cos(b)]])
R = Rx @ Ry
C = np.array([0.7, -0.4, -1.3])  # the camera centre in the world
T = -R @ C
cam = glscene.Camera(width=W, height=H, fx=120.0, fy=110.0, cx=79.3, cy=61.8, R=R, T=T, near=0.1, far=100.0)
player = glscene.Player(bundle)
out = player.render(cam, outputs=("depth", "instance", "normals"))
z, ids = out["depth"], out["instance"]
result("python_outputs_asked_for", sorted(out) == ["depth", "instance", "normals"] and z.dtype == np.float32
       and z.shape == (H, W) and ids.dtype == np.uint16 and out["normals"].shape == (H, W, 3))

# the wall's depth from the model: pixel (u, v) -> ray d = K^-1 (u, v, 1)
# in the camera, P = R^T (Zc d - T) in the world, P_z = 10
u, v = np.meshgrid(np.arange(W, dtype=np.float64), np.arange(H, dtype=np.float64))
d = np.stack([(u - cam.K[0, 2]) / cam.K[0, 0], (v - cam.K[1, 2]) / cam.K[1, 1], np.ones_like(u)], axis=-1)
Rtd = d @ R  # rows: R^T d
Zexp = (10.0 + (R.T @ T)[2]) / Rtd[..., 2]
wall_id = [i for i in range(1, player.instance_count + 1) if player.instance_path(i) == "Wall"]
tile_id = [i for i in range(1, player.instance_count + 1) if player.instance_path(i) == "Wall > parts.Tile#1"]
on_wall = ids == (wall_id[0] if wall_id else -1)
err = np.abs(z[on_wall] - Zexp[on_wall]) / Zexp[on_wall]
result("python_depth_camera_model", on_wall.sum() > W * H // 2 and err.max() <= 2 ** -21,
       "%d wall pixels, largest relative error %.3g" % (on_wall.sum(), err.max() if err.size else -1))
result("python_instance_paths", len(wall_id) == 1 and len(tile_id) == 1 and player.instance_count == 2
       and (ids == tile_id[0]).sum() > 0 and player.instance_path(0) is None)

# the tile moved 3 further along its z: its pixels' depth grows (the tile's
# plane is z = 8 in the world), and it covers fewer pixels
player.move("mover", np.eye(3), [0, 0, 3])
z2, ids2 = (lambda o: (o["depth"], o["instance"]))(player.render(cam, outputs=("depth", "instance")))
on_tile = ids2 == tile_id[0]
Zt = (8.0 + (R.T @ T)[2]) / Rtd[..., 2]
terr = np.abs(z2[on_tile] - Zt[on_tile]) / Zt[on_tile]
result("python_move_instance", 0 < on_tile.sum() < (ids == tile_id[0]).sum() and terr.max() <= 2 ** -21,
       "%d tile pixels after, %d before, relative error %.3g" % (on_tile.sum(), (ids == tile_id[0]).sum(),
                                                                 terr.max() if terr.size else -1))
player.move("mover")
result("python_move_back", np.array_equal(player.render(cam, outputs=("depth",))["depth"], z))


def raises(call, want):
    try:
        call()
    except glscene.Error as e:
        return str(e) == want, str(e)
    return False, "no exception"


good, got = raises(lambda: player.move("mvoer", np.eye(3), [0, 0, 1]), "the scene has no instance named 'mvoer'")
result("python_error_move", good, got)
good, got = raises(lambda: glscene.Camera(width=W, height=H, fx=0, fy=1, cx=0, cy=0),
                   "camera: fx must be > 0 (focal length in pixels)")
result("python_error_camera", good, got)
missing = os.path.join(TMP, "missing.glsb")
try:
    glscene.Player(missing)
    result("python_error_open", False, "no exception")
except glscene.Error as e:
    result("python_error_open", str(e).startswith(missing + ": "), str(e))
player.close()

# the demo: the image byte for byte as glsplay's PNG, depth as its PFM
demo = os.path.join(TMP, "demo.glsb")
glscene.compile("examples/demo/Demo.scene", ["examples/demo", os.path.join(BUILD, "textures")], demo)
left = "examples/demo/left.cam"
subprocess.run([os.path.join(BUILD, "glsplay"), demo, "--camera", left, "--aa", "4", "--background",
                "0.55,0.7,0.9", "-o", os.path.join(TMP, "play")], check=True)
with glscene.Player(demo, aa=4, background=(0.55, 0.7, 0.9)) as p:
    o = p.render(glscene.Camera.from_file(left), outputs=("image", "depth"))
png = cv2.imread(os.path.join(TMP, "play", "left", "image_000000.png"), cv2.IMREAD_UNCHANGED)
pfm = cv2.imread(os.path.join(TMP, "play", "left", "depth_000000.pfm"), cv2.IMREAD_UNCHANGED)
result("python_image_equals_glsplay_png", png is not None and np.array_equal(o["image"], png[..., ::-1]),
       "differs in %d values" % (np.count_nonzero(o["image"] != png[..., ::-1]) if png is not None else -1))
result("python_depth_equals_glsplay_pfm", pfm is not None and np.array_equal(o["depth"], pfm))

# the same camera by numbers goes through glscene_render: the same arrays
# as the run's (a file's camera); the instance ids as the run's, uint16
lc = glscene.Camera.from_file(left)
byn = glscene.Camera(lc.width, lc.height, lc.K[0, 0], lc.K[1, 1], lc.K[0, 2], lc.K[1, 2], R=lc.R, T=lc.T,
                     near=lc.near, far=lc.far, name="left")
with glscene.Player(demo, aa=4, background=(0.55, 0.7, 0.9)) as p:
    d = p.render(byn, outputs=("image", "depth", "instance", "normals"))
    f = p.render(lc, outputs=("image", "depth", "instance", "normals"))
result("python_numbers_camera_equals_file_run",
       all(np.array_equal(d[k], f[k], equal_nan=True) and d[k].dtype == f[k].dtype
           for k in ("image", "depth", "instance", "normals")),
       ", ".join("%s %s %s" % (k, d[k].dtype, f[k].dtype) for k in d))

# a rig gives a list of dicts, a camera one dict; the records' types
right = glscene.Camera.from_file("examples/demo/right.cam")
with glscene.Player(demo) as p:
    rig = p.render([lc, right], outputs=["disparity", "boxes", "landmarks", "points"])
    one = p.render(lc, outputs="depth")
result("python_rig_list_camera_dict", isinstance(rig, list) and len(rig) == 2 and isinstance(one, dict)
       and sorted(one) == ["depth"] and sorted(rig[1]) == ["boxes", "boxes_json", "disparity", "landmarks", "points"]
       and rig[0]["boxes"].dtype == glscene.BOX_DTYPE and rig[0]["landmarks"].dtype == glscene.LANDMARK_DTYPE
       and rig[0]["points"].dtype == glscene.POINT_DTYPE and rig[0]["disparity"].dtype == np.float32,
       repr((type(rig), sorted(rig[1]) if isinstance(rig, list) else None)))

# errors: the library's messages as glscene.Error
with glscene.Player(demo) as p:
    good, got = raises(lambda: p.render(lc, outputs=["depht"]), "--outputs takes a comma-separated list of: "
                       "image, depth, points, edges, disparity, disparity16, depth16, landmarks, instance, class, "
                       "coco, normals, flow, boxes, coverage, edge_segments (not 'depht'); did you mean 'depth'?")
    result("python_error_output_word", good, got)
    good, got = raises(lambda: p.render(glscene.Camera.from_text("width 64\nheight 48\nfx -1\n", name="broken")),
                       "")
    result("python_error_camera_text_located", got.startswith("broken:3:") and ": error: " in got, got)
    good, got = raises(lambda: p.render(lc, outputs="flow"), "--outputs flow needs a --trajectory: the flow goes "
                       "from each frame to the next")
    result("python_error_flow_needs_trajectory", good, got)
    good, got = raises(lambda: p.render([lc, right], outputs="image_float"), "")
    result("python_error_image_float_of_a_run", got.startswith("image_float is the float image of a single"), got)
good, got = raises(lambda: p.render(lc), "the player is closed")
result("python_error_closed", good, got)
good, got = raises(lambda: glscene.compile("color(1, 0, 0;\n", out=os.path.join(TMP, "t.glsb")), "")
result("python_compile_text_error", got.startswith("<scene text>:1:") and ": error: " in got, got)
t = glscene.compile("color(1, 0, 0);\npoly { vert(-1, -1, 5); vert(1, -1, 5); vert(0, 1, 5); }\n",
                    out=os.path.join(TMP, "t.glsb"))
with glscene.Player(t) as p:
    z = p.render(glscene.Camera(64, 48, 50, 50, 31.5, 23.5), outputs="depth")["depth"]
result("python_compile_text", t == os.path.join(TMP, "t.glsb") and abs(z[24, 32] - 5.0) <= 5.0 * 2e-7, str(z[24, 32]))
# --aa exact from Python: the image is glsplay's --aa exact image, and
# coverage sums to 1 over each pixel the triangle touches (the background
# is id 0: its rest)
tcam = os.path.join(TMP, "t.cam")
with open(tcam, "w") as f:
    f.write("width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n")
with glscene.Player(t, aa="exact") as p:
    ex = p.render(glscene.Camera.from_file(tcam), outputs=["image", "coverage", "edge_segments"])
subprocess.run([os.path.join(BUILD, "glsplay"), t, "--camera", tcam, "--aa", "exact", "--outputs", "image",
                "-o", os.path.join(TMP, "ex")], check=True)
want = cv2.imread(os.path.join(TMP, "ex", "t", "image_000000.png"))[:, :, ::-1]
cov = ex["coverage"]
sums = np.zeros((48, 64))
np.add.at(sums, (cov["y"], cov["x"]), cov["area"])
touched = np.zeros((48, 64), bool)
touched[cov["y"][cov["id"] > 0], cov["x"][cov["id"] > 0]] = True
result("python_exact_image_and_coverage", cov.dtype == glscene.COVERAGE_DTYPE and np.array_equal(ex["image"], want)
       and touched.sum() > 100 and np.abs(sums[touched] - 1).max() < 1e-9,
       "%d pixels touched, worst |sum - 1| %g, image equal %s" % (touched.sum(), np.abs(sums[touched] - 1).max(),
                                                                   np.array_equal(ex["image"], want)))
# the default (aa="auto", glsplay's): exact coverage, through glscene_render
# (a camera from numbers) and through a run (coverage), the same image as
# aa="exact"; aa=1 is one sample a pixel, another image
tc = glscene.Camera.from_file(tcam)
with glscene.Player(t) as p:
    d_direct = p.render(glscene.Camera(64, 48, 50, 50, 31.5, 23.5), outputs="image")["image"]
    d_run = p.render(tc, outputs=["image", "coverage"])
with glscene.Player(t, aa=1) as p:
    one = p.render(tc, outputs="image")["image"]
result("python_default_is_exact", np.array_equal(d_direct, want) and np.array_equal(d_run["image"], want)
       and np.array_equal(d_run["coverage"], cov) and not np.array_equal(one, want),
       "direct %s, run %s, one sample differs %s" % (np.array_equal(d_direct, want), np.array_equal(d_run["image"], want),
                                                     not np.array_equal(one, want)))
# edge_segments: the triangle's three edges, projected: (-1,-1,5), (1,-1,5),
# (0,1,5) through fx = fy = 50, (cx, cy) = (31.5, 23.5): each segment on one
# of them within 1e-9 px, the triangle's id on one side and 0 on the other
corners = [(31.5 + 10 * x, 23.5 + 10 * y) for x, y in ((-1, -1), (1, -1), (0, 1))]
seg = ex["edge_segments"]


def off_edges(s):
    worst = np.inf
    for k in range(3):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 3]
        n = np.hypot(bx - ax, by - ay)
        d = max(abs((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / n for x, y in ((s["x0"], s["y0"]), (s["x1"], s["y1"])))
        worst = min(worst, d)
    return worst


worst = max(off_edges(s) for s in seg) if len(seg) else np.inf
length = float(np.hypot(seg["x1"] - seg["x0"], seg["y1"] - seg["y0"]).sum())
perimeter = sum(np.hypot(corners[(k + 1) % 3][0] - corners[k][0], corners[(k + 1) % 3][1] - corners[k][1]) for k in range(3))
result("python_exact_edge_segments", seg.dtype == glscene.EDGE_SEGMENT_DTYPE and worst < 1e-9
       and abs(length - perimeter) < 1e-6 and bool((np.minimum(seg["left"], seg["right"]) == 0).all())
       and bool((np.maximum(seg["left"], seg["right"]) > 0).all()),
       "%d segments, worst off an edge %g px, length %.9f of the perimeter %.9f" % (len(seg), worst, length, perimeter))
# move() reaches glscene_render's frames only: a run refuses rather than
# render without the move
with glscene.Player(bundle) as p:
    p.move("mover", np.eye(3), [0, 0, 3])
    good, got = raises(lambda: p.render(cam, outputs="boxes"), "")
    result("python_error_move_then_run", got.startswith("move() posed mover, which a render of"), got)
    p.move("mover")
    result("python_move_back_then_run", sorted(p.render(cam, outputs="boxes")) == ["boxes", "boxes_json"])

# a trajectory: its frames listed by sequence, a frame it has not said in
# the caller's words (not the --frames the run was given)
traj = os.path.join(TMP, "traj.txt")
with open(traj, "w") as f:
    f.writelines("%d %g 1 0 0 0 1 0 0 0 1 0 0 %g\n" % (k, 0.1 * k, -0.5 * k) for k in (3, 4, 6))
with glscene.Player(bundle) as p:
    seq = [(k, o["depth"][24 * 0 + 60, 80]) for k, o in p.sequence(cam, traj, outputs="depth")]
    good, got = raises(lambda: p.render(cam, outputs="depth", frame=5, trajectory=traj),
                       "%s has no frame 5 (its frames: 3 to 6, 3 rows)" % traj)
result("python_sequence_frames", [k for k, _ in seq] == [3, 4, 6] and seq[0][1] > seq[1][1] > seq[2][1], repr(seq))
result("python_error_frame_not_in_trajectory", good, got)

# the player keeps its settings' run open (one glscene_play, which the
# library keeps open: test_glscene's test_glscene_play_render_keeps_run):
# a sequence's frames and a render after it with the same settings render
# in it; other outputs begin another; a trajectory rewritten since the
# run began begins another, which reads it
with glscene.Player(bundle) as p:
    runs = []
    for k, o in p.sequence(cam, traj, outputs="depth"):
        runs.append(getattr(p, "_run", None))
        if k == 3:
            d3 = o["depth"]
    again = p.render(cam, outputs="depth", frame=3, trajectory=traj)["depth"]
    runs.append(getattr(p, "_run", None))
    result("python_player_keeps_run", len(runs) == 4 and runs[0] is not None and all(r is runs[0] for r in runs)
           and np.array_equal(again, d3, equal_nan=True), repr(runs))
    p.render(cam, outputs="instance", frame=3, trajectory=traj)
    other = getattr(p, "_run", None)
    d3 = p.render(cam, outputs="depth", frame=3, trajectory=traj)["depth"]  # its run, then the file rewritten
    with open(traj, "w") as f:  # frame 3 moved 1 further back, the file longer
        f.writelines("%d %g 1 0 0 0 1 0 0 0 1 0 0 %g\n" % (k, 0.1 * k, -0.5 * k - 1.0) for k in (3, 4, 6))
    moved = p.render(cam, outputs="depth", frame=3, trajectory=traj)["depth"]
    result("python_other_settings_begin_a_run", other is not None and other is not runs[0])
    result("python_rewritten_file_begins_a_run", not np.array_equal(moved, d3, equal_nan=True))

# sensor keys by name through from_opencv (R as a 3x3, the noise keyed by
# the camera's name and frame): the same image as the camera file's
sf = glscene.Camera.from_file("examples/demo/left_sensor.cam")
sn = glscene.Camera.from_opencv(lc.K, None, lc.R, lc.T, size=(640, 480), near=0.1, far=500.0, name="left_sensor",
                                keys={"vignetting": "cos4", "gain": 1.2, "shot_noise": 300, "read_noise": 0.01,
                                      "noise_seed": 1})
with glscene.Player(demo) as p:
    a, b = (p.render(c, outputs="image", frame=3)["image"] for c in (sf, sn))
    c0 = p.render(sf, outputs="image", frame=4)["image"]
result("python_from_opencv_sensor_keys", np.array_equal(a, b) and not np.array_equal(a, c0),
       "differs in %d values" % np.count_nonzero(a != b))
