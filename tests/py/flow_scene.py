"""The flow and boxes tests' scene, written out so that the tests share
one description (tests/e2e/outputs_flow.sh, tests/py/check_flow.py).

World frame: the camera frame of frame 0 (x right, y down, z forward).
A wall at z = 20 (x -100..100, y -5..2), a floor at y = 2 (z 0.5..20),
a red unit box "mover" (objects.Box: x -0.5..0.5, y 0..1, z -0.5..0.5 in
its frame) placed at (0, 1, 8) and moved by --motion: MOVE per frame and
turned by TURN degrees per frame about its vertical axis,
a green unit box at (-2.5, 1, 10) that stays.  The rig moves forward and
yaws; camera "cam" is the rig's camera (identity relative to it)."""
import numpy as np

import gt_checks

W, H = 320, 240
FX, FY, CX, CY = 300.0, 300.0, 159.5, 119.5
NEAR, FAR = 0.1, 100.0
MOVER_AT = np.array([0.0, 1.0, 8.0])
STILL_AT = np.array([-2.5, 1.0, 10.0])
MOVE = np.array([0.3, 0.0, 0.0])  # per frame
TURN = 6.0  # degrees per frame, about the box's y axis
BOX_LO = np.array([-0.5, 0.0, -0.5])
BOX_HI = np.array([0.5, 1.0, 0.5])
NFRAMES = 3
K = np.array([[FX, 0, CX], [0, FY, CY], [0, 0, 1.0]])

SCENE = """// flow test scene (tests/py/flow_scene.py)
poly { col(0.6, 0.6, 0.6); vert(-100, -5, 20); vert(100, -5, 20); vert(100, 2, 20); vert(-100, 2, 20); }
poly { col(0.3, 0.5, 0.3); vert(-100, 2, 0.5); vert(100, 2, 0.5); vert(100, 2, 20); vert(-100, 2, 20); }
push; trans(0, 1, 8); call("objects.BoxRed", "mover"); pop;
push; trans(-2.5, 1, 10); call("objects.BoxGreen"); pop;
"""

CAM = gt_checks.camera_text("rig", W, H, FX, FY, CX, CY, NEAR, FAR)


def rig_pose(k):
    """World -> rig (R, T) of frame k: the rig 0.25 forward per frame,
    yawed by 1.5 degrees per frame about the vertical (y) axis."""
    a = np.radians(1.5 * k)
    Rw = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])  # rig -> world
    C = np.array([0.0, 0.0, 0.25 * k])
    R = Rw.T
    return R, -R @ C


def mover_motion(k):
    """The mover's motion of frame k, object-to-parent (R, T)."""
    a = np.radians(TURN * k)
    R = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    return R, MOVE * k


def box_pose(k, moving):
    """Box-frame to world (R, t) of the mover (moving) or the still box."""
    if not moving:
        return np.eye(3), STILL_AT
    R, T = mover_motion(k)
    return R, MOVER_AT + T


def trajectory_text(pose=rig_pose, n=NFRAMES):
    rows = []
    for k in range(n):
        R, T = pose(k)
        rows.append("%d %r %s %s" % (k, 0.1 * k, " ".join(repr(float(x)) for x in R.ravel()),
                                     " ".join(repr(float(x)) for x in T)))
    return "# glsroad trajectory 1\n" + "\n".join(rows) + "\n"


def motion_text(n=NFRAMES):
    rows = []
    for k in range(n):
        R, T = mover_motion(k)
        rows.append(" ".join(repr(float(x)) for x in np.hstack([R, T[:, None]]).ravel()))
    return "\n".join(rows) + "\n"


def write(d):
    import os
    with open(os.path.join(d, "Flow.scene"), "w") as f:
        f.write(SCENE)
    with open(os.path.join(d, "cam.cam"), "w") as f:
        f.write(CAM)
    with open(os.path.join(d, "trajectory.txt"), "w") as f:
        f.write(trajectory_text())
    with open(os.path.join(d, "mover.txt"), "w") as f:
        f.write(motion_text())


if __name__ == "__main__":
    import sys
    write(sys.argv[1])
