"""What the Python checks share: the "ok NAME" / "FAIL NAME: why" lines
tests/run.sh counts, writing a file with its directories, and running a
tool (an exception with its message when it fails)."""
import os
import subprocess
import sys


def ok(name):
    print("ok " + name)


def fail(name, why):
    print("FAIL %s: %s" % (name, why))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def run(*args):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("%s: exit %d: %s" % (args[0], r.returncode, r.stderr.strip()))
    return r.stdout


class Checks:
    """A check script's results: result() prints the line and remembers a
    failure (passed says whether all passed); run() runs a tool that must
    exit with want_rc, else ends the script with "FAIL SETUP: ...", SETUP
    the name given."""

    def __init__(self, setup):
        self.setup = setup
        self.passed = True

    def result(self, name, good, why=''):
        self.passed &= bool(good)
        print(('ok %s' % name) if good else ('FAIL %s: %s' % (name, why)))

    def run(self, args, want_rc=0):
        p = subprocess.run(args, capture_output=True, text=True)
        if p.returncode != want_rc:
            raise SystemExit('FAIL %s: %s: exit %d: %s' % (self.setup, ' '.join(args), p.returncode, p.stderr))
        return p

    def exit(self):
        sys.exit(0 if self.passed else 1)


def look_at(C, target):
    """R, T of a camera at C looking at target, image x along
    world -y x forward (the shadow checks' views)."""
    import numpy as np
    C = np.asarray(C, float)
    z = np.asarray(target, float) - C
    z /= np.linalg.norm(z)
    x = np.cross([0.0, -1.0, 0.0], z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    R = np.array([x, y, z])
    return R, -R @ C


def render_green(BIN, d, R, T, size, far):
    """Compile d/Top.scene, render it through a pinhole camera (W, H, F =
    size, principal point at the centre) with R, T: the image's green
    channel as floats."""
    import cv2
    W, H, F = size
    cam = os.path.join(d, "cam.cam")
    write(cam, "width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR %s\nT %s\nnear 0.1\nfar %r\n" %
          (W, H, F, F, (W - 1) / 2, (H - 1) / 2, " ".join(repr(float(x)) for x in R.ravel()),
           " ".join(repr(float(x)) for x in T), far))
    run(os.path.join(BIN, "glsc"), "-o", os.path.join(d, "s.glsb"), os.path.join(d, "Top.scene"))
    run(os.path.join(BIN, "glsplay"), os.path.join(d, "s.glsb"), "--camera", cam, "--outputs", "image", "-o",
        os.path.join(d, "out"))
    return cv2.imread(os.path.join(d, "out", "cam", "image_000000.png"), cv2.IMREAD_COLOR)[:, :, 1].astype(float)
