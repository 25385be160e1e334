"""What the ground-truth checkers (check_flow.py, check_boxes.py) share:
one glstest.Checks for their "ok NAME" / "FAIL NAME: why" lines (CHECKS,
result), and the text of a pinhole camera file (spec/camera.md)."""
from glstest import Checks

CHECKS = Checks("gt_checks_setup")
result = CHECKS.result


def camera_text(pose, w, h, fx, fy, cx, cy, near=0.1, far=100.0):
    """An identity-pose camera file (R = I, T = 0) of this size and K."""
    return ("pose %s\nwidth %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\n"
            "R 1 0 0  0 1 0  0 0 1\nT 0 0 0\nnear %r\nfar %r\n" % (pose, w, h, fx, fy, cx, cy, near, far))
