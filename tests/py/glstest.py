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
    """A check script's results: result() prints the line, remembers a
    failure (passed says whether all passed) and returns good; run() runs a tool that must
    exit with want_rc, else ends the script with "FAIL SETUP: ...", SETUP
    the name given."""

    def __init__(self, setup):
        self.setup = setup
        self.passed = True

    def result(self, name, good, why=''):
        self.passed &= bool(good)
        print(('ok %s' % name) if good else ('FAIL %s: %s' % (name, why)))
        return good

    def run(self, args, want_rc=0):
        p = subprocess.run(args, capture_output=True, text=True)
        if p.returncode != want_rc:
            raise SystemExit('FAIL %s: %s: exit %d: %s' % (self.setup, ' '.join(args), p.returncode, p.stderr))
        return p

    def exit(self):
        sys.exit(0 if self.passed else 1)

    def grey(self, path):
        """The first channel of an 8- or 16-bit image as floats in [0, 1];
        no image ends the script with "FAIL SETUP: cannot read PATH"."""
        import cv2
        import numpy as np
        im = cv2.imread(path, cv2.IMREAD_UNCHANGED)
        if im is None:
            raise SystemExit('FAIL %s: cannot read %s' % (self.setup, path))
        return im[:, :, 0].astype(np.float64) / (65535.0 if im.dtype == np.uint16 else 255.0)

    def moving_square(self, BIN, D, z):
        """A white 4 x 4 square at depth z moving +x one unit a frame
        (frames 0 to 3): D/src/Sq.scene, D/src/Moving.scene (the square
        called "mover"), compiled into D/moving.glsb, and its motion file
        D/mover.txt (spec/road.md)."""
        write(D + '/src/Sq.scene', 'color(1, 1, 1);\npoly { vert(-2, -2, 0); vert(2, -2, 0); vert(2, 2, 0); vert(-2, 2, 0); }\n')
        write(D + '/src/Moving.scene', 'push; trans(0, 0, %r); call("Sq", "mover"); pop;\n' % z)
        self.run([BIN + '/glsc', '-I', D + '/src', '-o', D + '/moving.glsb', 'Moving'])
        write(D + '/mover.txt', '# glsroad motion 1\n' + ''.join('%d %d 1 0 0 0 1 0 0 0 1 %d 0 0\n' % (k, k, k)
                                                              for k in range(4)))


def read_cam(path):
    """K (with skew), R, T, width, height of a pinhole camera file
    (spec/camera.md), read independently of the player."""
    import numpy as np
    c = {}
    for line in open(path):
        line = line.split('#')[0].split()
        if line:
            c[line[0]] = [float(x) for x in line[1:]]
    K = np.array([[c['fx'][0], c.get('skew', [0])[0], c['cx'][0]],
                  [0, c['fy'][0], c['cy'][0]], [0, 0, 1]])
    R = np.array(c['R']).reshape(3, 3)
    T = np.array(c['T'])
    return K, R, T, int(c['width'][0]), int(c['height'][0])


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
    channel as floats.  One sample a pixel (--aa 1): the checks hold each
    pixel centre to a closed form, and a scene without shadows would
    otherwise be drawn by exact coverage (glsplay's default)."""
    import cv2
    W, H, F = size
    cam = os.path.join(d, "cam.cam")
    write(cam, "width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\nR %s\nT %s\nnear 0.1\nfar %r\n" %
          (W, H, F, F, (W - 1) / 2, (H - 1) / 2, " ".join(repr(float(x)) for x in R.ravel()),
           " ".join(repr(float(x)) for x in T), far))
    run(os.path.join(BIN, "glsc"), "-o", os.path.join(d, "s.glsb"), os.path.join(d, "Top.scene"))
    run(os.path.join(BIN, "glsplay"), os.path.join(d, "s.glsb"), "--camera", cam, "--outputs", "image", "--aa",
        "1", "-o", os.path.join(d, "out"))
    return cv2.imread(os.path.join(d, "out", "cam", "image_000000.png"), cv2.IMREAD_COLOR)[:, :, 1].astype(float)


def undistort_iter(pts, K, dist, crit):
    """Normalised rays of distorted pixels pts, solved to criteria crit:
    cv2.undistortPointsIter in OpenCV 4; OpenCV 5 dropped it and gave
    cv2.undistortPoints the criteria (a GPU machine's pip OpenCV is 5)."""
    import cv2
    f = getattr(cv2, "undistortPointsIter", None)
    if f is not None:
        return f(pts, K, dist, None, None, crit)
    return cv2.undistortPoints(pts, K, dist, None, None, criteria=crit)
