#!/usr/bin/python3
"""make bench-gpu, inputs: the scenes, cameras and camera paths that
bench/gpu.sh times (written here, compiled there).  Deterministic.

usage: gpu_inputs.py DIR

DIR/random.scene   100,000 triangles scattered in random order through a
                   200 m cube, random flat colours (the scene that defeats
                   spatial chunking: every triangle alone in its cell)
DIR/forest.scene   100 x 100 trees (objects.Cylinder trunk, objects.Sphere
                   crown: 4,352 triangles each) on a jittered 10 m grid
DIR/orbit_random.txt, orbit_forest.txt
                   camera paths (glsroad trajectory format, spec/road.md):
                   the random cube seen from outside, the forest from 60 m up
                   at its edge, the camera turning through every direction of
                   a full circle, 400 frames
DIR/cam_640.cam, cam_1920.cam
                   the rig camera (pose rig, identity) at 640x480 and
                   1920x1080, the same 67.4-degree horizontal field of view
"""
import math
import random
import sys

FRAMES = 400


def cam(path, w, h):
    fx = w / (2 * math.tan(math.radians(67.38) / 2))
    with open(path, "w") as f:
        f.write("pose rig\nwidth %d\nheight %d\nfx %.17g\nfy %.17g\ncx %.17g\ncy %.17g\n"
                "R 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.5\nfar 5000\n" % (w, h, fx, fx, (w - 1) / 2, (h - 1) / 2))


def look(c, p):
    """world-to-rig R (rows: right, down, forward; world y up) and T = -R c"""
    f = [p[i] - c[i] for i in range(3)]
    n = math.sqrt(sum(x * x for x in f))
    f = [x / n for x in f]
    r = [f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0]  # f x (0, 1, 0)
    n = math.sqrt(sum(x * x for x in r))
    r = [x / n for x in r]
    d = [f[1] * r[2] - f[2] * r[1], f[2] * r[0] - f[0] * r[2], f[0] * r[1] - f[1] * r[0]]  # f x r
    R = r + d + f
    T = [-(R[3 * i] * c[0] + R[3 * i + 1] * c[1] + R[3 * i + 2] * c[2]) for i in range(3)]
    return R, T


def orbit(path, centre, radius, height, target_height):
    with open(path, "w") as f:
        f.write("# glsroad trajectory 1\n")
        for k in range(FRAMES):
            a = 2 * math.pi * k / FRAMES
            c = (centre[0] + radius * math.cos(a), height, centre[2] + radius * math.sin(a))
            R, T = look(c, (centre[0], target_height, centre[2]))
            f.write("%d %.17g %s %s\n" % (k, k / 25.0, " ".join("%.17g" % x for x in R), " ".join("%.17g" % x for x in T)))


def random_scene(path):
    rnd = random.Random(20261128)
    with open(path, "w") as f:
        f.write("// bench-gpu: 100,000 triangles in random order in a 200 m cube\n")
        for _ in range(100000):
            cx, cy, cz = (rnd.uniform(-100, 100) for _ in range(3))
            f.write("color(%.3f, %.3f, %.3f); poly {" % (rnd.random(), rnd.random(), rnd.random()))
            for _ in range(3):
                f.write(" vert(%.3f, %.3f, %.3f);" % (cx + rnd.uniform(-2, 2), cy + rnd.uniform(-2, 2), cz + rnd.uniform(-2, 2)))
            f.write(" }\n")


def forest_scene(path):
    rnd = random.Random(7)
    with open(path, "w") as f:
        f.write("// bench-gpu: 100 x 100 trees, 10 m apart, jittered\n")
        for i in range(100):
            for j in range(100):
                x, z = 10 * i + rnd.uniform(-3, 3), 10 * j + rnd.uniform(-3, 3)
                f.write("push; trans(%.3f, 0, %.3f); push; scale(0.5, 3, 0.5); call(\"objects.Cylinder\"); pop; "
                        "trans(0, 2.5, 0); scale(5, 6, 5); call(\"objects.Sphere\"); pop;\n" % (x, z))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: gpu_inputs.py DIR")
    d = sys.argv[1]
    cam(d + "/cam_640.cam", 640, 480)
    cam(d + "/cam_1920.cam", 1920, 1080)
    random_scene(d + "/random.scene")
    forest_scene(d + "/forest.scene")
    orbit(d + "/orbit_random.txt", (0, 0, 0), 260, 40, 0)
    orbit(d + "/orbit_forest.txt", (500, 0, 500), 560, 60, 0)


if __name__ == "__main__":
    main()
