"""Seconds of a 20-frame Player.sequence of the demo road (docs/python.md
"A sequence loads the scene once"): glsroad writes the road, glsc compiles
it, and the Python binding renders frames 200 to 219 of its trajectory
through the stereo rig (image and depth, the vehicles moving as --motion).
A measurement, not a test: it prints the figure and checks nothing.
    python3 bench/python_sequence.py BUILD [LIBRARY]
LIBRARY: the libglscene.so.0 to time (default BUILD's), so that two
builds (before and after a change) are timed in the same run."""
import glob
import os
import subprocess
import sys
import tempfile
import time

BUILD = sys.argv[1]
os.environ["GLSCENE_LIBRARY"] = sys.argv[2] if len(sys.argv) > 2 else os.path.join(BUILD, "libglscene.so.0")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import glscene  # noqa: E402

with tempfile.TemporaryDirectory() as t:
    road = os.path.join(t, "road")
    subprocess.run([os.path.join(BUILD, "glsroad"), "examples/road/demo.road", "-o", road], check=True,
                   stdout=subprocess.DEVNULL)
    bundle = os.path.join(t, "road.glsb")
    subprocess.run([os.path.join(BUILD, "glsc"), "-I", os.path.join(BUILD, "scenelib.glsb"), "-I", road, "-o",
                    bundle, os.path.join(road, "road.scene")], check=True)
    motion = {os.path.basename(m)[:-4]: m for m in sorted(glob.glob(os.path.join(road, "motion", "*.txt")))}
    rig = [glscene.Camera.from_file("examples/road/rig/%s.cam" % s) for s in ("left", "right")]
    with glscene.Player(bundle, background=(0.55, 0.7, 0.9)) as player:
        t0 = time.perf_counter()
        n = sum(1 for _ in player.sequence(rig, os.path.join(road, "trajectory.txt"), outputs=["image", "depth"],
                                           motion=motion, frames=range(200, 220)))
        el = time.perf_counter() - t0
print("%d frames of 2 cameras: %.2f s, %.3f s a frame (%s)" % (n, el, el / n, os.environ["GLSCENE_LIBRARY"]))
