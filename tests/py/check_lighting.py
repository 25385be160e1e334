"""Lighting (issue 16, spec/camera.md "Lighting"), rendered by glsplay and
checked against closed forms computed here in numpy, never against numbers
the player printed:

- a finely tessellated unit sphere with analytic normals (normal(...)),
  lit by a directional light and an ambient one: every pixel well inside
  the silhouette against 255 * albedo * (ambient + max(0, n.l)), n the
  true sphere normal where the pixel's ray meets the sphere;
- a plane without normals (flat normal, wound away from the camera) lit by
  a point light declared in a called object placed by trans: against
  255 * (n.L) / (1 + k d^2), the light where the transforms put it;
- a black plane with a Phong highlight: every pixel against
  255 * s * max(0, r.v)^e, and the highlight's centroid against the
  projection of the mirror point the reflection law gives;
- ground truth untouched: depth and instance ids of the lit sphere equal
  those of the same scene without its lights, byte for byte;
- far from the origin: the point-lit plane moved 1e6 units with its
  camera gives the same image, byte for byte.

Usage: check_lighting.py BIN TMPDIR.  Prints "ok NAME" / "FAIL NAME: why".
"""
import os
import sys

import cv2
import numpy as np

from glstest import fail, ok, run, write

BIN, TMP = sys.argv[1], sys.argv[2]


def camera(name, w, h, f, R, T):
    text = "width %d\nheight %d\nfx %r\nfy %r\ncx %r\ncy %r\n" % (w, h, f, f, (w - 1) / 2, (h - 1) / 2)
    text += "R " + " ".join(repr(float(x)) for x in np.asarray(R).ravel()) + "\n"
    text += "T " + " ".join(repr(float(x)) for x in T) + "\nnear 0.1\nfar 100\n"
    path = os.path.join(TMP, name + ".cam")
    write(path, text)
    return path


def render(scene_dir, top, cam, outputs="image"):
    glsb = os.path.join(TMP, os.path.basename(scene_dir) + ".glsb")
    run(os.path.join(BIN, "glsc"), "-I", scene_dir, "-o", glsb, os.path.join(scene_dir, top))
    out = os.path.join(TMP, "out_" + os.path.basename(scene_dir))
    # --aa 1: GL's shader at each pixel centre, held to the closed forms
    # (exact coverage's lighting, the default's: player_aa_exact_shade.sh)
    run(os.path.join(BIN, "glsplay"), glsb, "--camera", cam, "--outputs", outputs, "--aa", "1", "-o", out)
    cname = os.path.splitext(os.path.basename(cam))[0]
    return os.path.join(out, cname)


def image(d):
    bgr = cv2.imread(os.path.join(d, "image_000000.png"), cv2.IMREAD_COLOR)
    return bgr[:, :, ::-1].astype(np.float64)


def rays(w, h, f, R, T):
    """World ray directions (unnormalised) of every pixel centre, and the
    camera centre: OpenCV's pinhole, pixel centres at integers."""
    u, v = np.meshgrid(np.arange(w, dtype=np.float64), np.arange(h, dtype=np.float64))
    dc = np.stack([(u - (w - 1) / 2) / f, (v - (h - 1) / 2) / f, np.ones_like(u)], axis=-1)
    R = np.asarray(R, dtype=np.float64)
    return dc @ R, -R.T @ np.asarray(T, dtype=np.float64)  # R^T d for each row vector d


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


# ---- the sphere ------------------------------------------------------------
NLAT, NLON = 96, 192
L_DIR = np.array([0.3, 0.5, 1.0])
AMBIENT = 0.1
sphere = ["const nl = %d;" % NLAT, "const nm = %d;" % NLON, "color(0.8, 0.6, 0.4);",
          "repeat(i, 0, nl) { qstrip { repeat(j, 0, nm + 1) {",
          "    const a0 = 180 * i / nl - 90; const a1 = 180 * (i + 1) / nl - 90; const b = 360 * j / nm;",
          "    normal(cos(a0) * cos(b), sin(a0), cos(a0) * sin(b)); vert(cos(a0) * cos(b), sin(a0), cos(a0) * sin(b));",
          "    normal(cos(a1) * cos(b), sin(a1), cos(a1) * sin(b)); vert(cos(a1) * cos(b), sin(a1), cos(a1) * sin(b));",
          "} } }"]
lights = ["ambient(%r, %r, %r);" % (AMBIENT, AMBIENT, AMBIENT),
          "light(directional, %r, %r, %r, 1, 1, 1);" % tuple(L_DIR)]
write(os.path.join(TMP, "sphere", "Top.scene"), "\n".join(lights + sphere) + "\n")
write(os.path.join(TMP, "sphere_unlit", "Top.scene"), "\n".join(sphere) + "\n")
W, H, F = 400, 400, 500.0
R_S, T_S = np.diag([1.0, -1.0, -1.0]), [0.0, 0.0, 4.0]
cam_s = camera("sph", W, H, F, R_S, T_S)
lit = render(os.path.join(TMP, "sphere"), "Top.scene", cam_s, "image,depth,instance")
unlit = render(os.path.join(TMP, "sphere_unlit"), "Top.scene", cam_s, "image,depth,instance")

img = image(lit)
d, C = rays(W, H, F, R_S, T_S)
d = unit(d)
b = d @ C                                   # |C + t d| = 1: t^2 + 2 b t + |C|^2 - 1 = 0
disc = b * b - (C @ C - 1.0)
inside = disc > (1 - 0.97 ** 2)             # rays passing within 0.97 of the centre
t = -b - np.sqrt(np.maximum(disc, 0))
n = C + t[..., None] * d                    # the true normal of the unit sphere
albedo = np.array([204, 153, 102]) / 255.0  # colour(0.8, 0.6, 0.4) as the RGBA8 vertex colour
shade = AMBIENT + np.maximum(0, n @ unit(L_DIR))
expect = np.clip(255 * albedo * shade[..., None], 0, 255)
err = np.abs(img - expect)[inside]
# tolerance: 8-bit rounding (0.5) plus the interpolation of normals over
# 1.875-degree facets (measured on llvmpipe: max 0.64 levels, mean 0.25)
TOL_MAX, TOL_MEAN = 1.0, 0.35
if inside.sum() > 40000 and err.max() <= TOL_MAX and err.mean() <= TOL_MEAN:
    ok("lighting_sphere_lambert")
else:
    fail("lighting_sphere_lambert", "%d pixels, max error %.3f (<= %g), mean %.3f (<= %g)" %
         (inside.sum(), err.max(), TOL_MAX, err.mean(), TOL_MEAN))
print("# sphere: %d pixels, max error %.3f levels, mean %.3f" % (inside.sum(), err.max(), err.mean()))

# ground truth is not photometric: depth and ids as without lights
same = all(open(os.path.join(lit, f), "rb").read() == open(os.path.join(unlit, f), "rb").read()
           for f in ("depth_000000.pfm", "instance_000000.png"))
if same:
    ok("lighting_ground_truth_unchanged")
else:
    fail("lighting_ground_truth_unchanged", "depth or instance ids differ between the lit and the unlit sphere")
# and the unlit sphere is drawn flat, in its colour (the path of before)
ui = image(unlit)[inside]
if np.all(ui == np.array([204, 153, 102])):
    ok("lighting_unlit_flat")
else:
    fail("lighting_unlit_flat", "the unlit sphere is not its flat colour")

# ---- the plane under a point light in a called, translated object ------------
K = 0.25
LAMP_AT = np.array([0.5, 0.0, -0.3]) + np.array([0.0, 2.0, 0.0])
plane = "color(1, 1, 1);\npoly { vert(-6, 0, -6); vert(6, 0, -6); vert(6, 0, 6); vert(-6, 0, 6); }\n"
write(os.path.join(TMP, "plane", "t", "Lamp.scene"), "light(point, 0, 2, 0, 1, 1, 1, %r);\n" % K)
write(os.path.join(TMP, "plane", "Top.scene"), plane + "push; trans(0.5, 0, -0.3); call(\"t.Lamp\"); pop;\n")
W2, H2, F2 = 320, 320, 200.0
R_P, T_P = np.array([[1.0, 0, 0], [0, 0, 1.0], [0, -1.0, 0]]), [0.0, 0.0, 8.0]   # from (0, 8, 0), looking down
cam_p = camera("down", W2, H2, F2, R_P, T_P)
img = image(render(os.path.join(TMP, "plane"), "Top.scene", cam_p))
d, C = rays(W2, H2, F2, R_P, T_P)
p = C + (-C[1] / d[..., 1])[..., None] * d   # on y = 0
on = (np.abs(p[..., 0]) < 5.9) & (np.abs(p[..., 2]) < 5.9)
to = LAMP_AT - p
d2 = np.sum(to * to, axis=-1)
expect = 255 * (to[..., 1] / np.sqrt(d2)) / (1 + K * d2)
err = np.abs(img - expect[..., None])[on]
# 8-bit rounding; per-pixel float evaluation adds < 0.01 level
if on.sum() > 50000 and err.max() <= 1.0:
    ok("lighting_plane_point_light")
else:
    fail("lighting_plane_point_light", "max error %.3f levels over %d pixels (<= 1)" % (err.max(), on.sum()))
print("# plane: %d pixels, max error %.3f levels, mean %.3f" % (on.sum(), err.max(), err.mean()))

# the same scene and camera 1e6 units from the origin (a multiple of the
# chunk cell, 64): the lights are composed in double and handed to GL
# relative to the camera, so the image is the same, byte for byte
D = np.array([64.0 * 2 ** 14, 0.0, -64.0 * 2 ** 13])
write(os.path.join(TMP, "far", "t", "Lamp.scene"), "light(point, 0, 2, 0, 1, 1, 1, %r);\n" % K)
write(os.path.join(TMP, "far", "Top.scene"), "trans(%r, %r, %r);\n" % tuple(D) + plane +
      "push; trans(0.5, 0, -0.3); call(\"t.Lamp\"); pop;\n")
cam_far = camera("downfar", W2, H2, F2, R_P, np.asarray(T_P) - R_P @ D)
far = image(render(os.path.join(TMP, "far"), "Top.scene", cam_far))
if np.array_equal(far, img):
    ok("lighting_far_from_origin")
else:
    fail("lighting_far_from_origin", "1e6 units away the image differs: max %g levels at %d pixels" %
         (np.abs(far - img).max(), int((far != img).any(axis=-1).sum())))

# ---- the Phong highlight -----------------------------------------------------
L_SPEC, SPEC, EXP = np.array([0.3, 1.0, 0.2]), 0.9, 200.0
write(os.path.join(TMP, "shiny", "Top.scene"),
      "light(directional, %r, %r, %r, 1, 1, 1);\nspecular(%r, %r, %r, %r);\ncolor(0, 0, 0);\n" %
      (tuple(L_SPEC) + (SPEC, SPEC, SPEC, EXP)) +
      "poly { normal(0, 1, 0); vert(-6, 0, -6); vert(6, 0, -6); vert(6, 0, 6); vert(-6, 0, 6); }\n")
img = image(render(os.path.join(TMP, "shiny"), "Top.scene", cam_p))[..., 1]
l = unit(L_SPEC)
r = np.array([-l[0], l[1], -l[2]])           # reflect(-l, n), n = (0, 1, 0)
v = unit(C - p)
expect = 255 * SPEC * np.maximum(0, v @ r) ** EXP
err = np.abs(img - expect)[on]
# the reflection law: the view ray of the mirror point is r, so it is at
# C - (C_y / r_y) r; its pixel by cv2.projectPoints
mirror = C - (C[1] / r[1]) * r
uv, _ = cv2.projectPoints(mirror.reshape(1, 1, 3), cv2.Rodrigues(R_P)[0], np.array(T_P),
                          np.array([[F2, 0, (W2 - 1) / 2], [0, F2, (H2 - 1) / 2], [0, 0, 1]]), None)
uv = uv.ravel()
top = img >= 0.8 * img.max()
vv, uu = np.nonzero(top)
wgt = img[top]
cu, cv_ = np.sum(uu * wgt) / np.sum(wgt), np.sum(vv * wgt) / np.sum(wgt)
off = np.hypot(cu - uv[0], cv_ - uv[1])
if err.max() <= 1.0 and off <= 0.5:
    ok("lighting_specular_reflection_law")
else:
    fail("lighting_specular_reflection_law", "max error %.3f levels (<= 1); highlight centroid (%.3f, %.3f), "
         "mirror point projects to (%.3f, %.3f): %.3f px apart (<= 0.5)" % (err.max(), cu, cv_, uv[0], uv[1], off))
print("# highlight: max error %.3f levels; centroid %.3f px from the mirror point" % (err.max(), off))
