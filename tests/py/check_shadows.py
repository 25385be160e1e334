"""Shadows (issue 16, spec/camera.md "Shadows"): a box standing on a
12 x 12 plane, under a directional light with shadows(2048), rendered by
glsplay and checked against the geometry computed here in numpy:

- the shadow boundary: a plane pixel is in shadow exactly when the ray
  from its point on the plane towards the light meets the box; every pixel
  whose observed state (lit or shadowed, by the value halfway between the
  closed-form lit and shadowed values) differs from that lies within
  BOUNDARY_PX of the boundary of the true shadow (box pixels counted as
  shadow, so that a gap between the box and its shadow, peter-panning, is
  inside the region and fails);
- contact (light at 45 degrees incidence, seen from the shadow's side, a
  box 5 cm thick): the above, and no lit plane pixel in the true shadow
  within 3 px of the box (no peter-panning gap);
- grazing (light at 80 degrees incidence): every plane pixel farther than
  BOUNDARY_PX from the true boundary equals the closed form (lit or
  shadowed) within 1 level: no acne on the lit plane, no light leaking
  into the shadow;
- far from the origin: the contact case moved 1e6 units with its camera
  gives the same image, byte for byte.

Usage: check_shadows.py BIN TMPDIR.  Prints "ok NAME" / "FAIL NAME: why"."""
import math
import os
import sys

import cv2
import numpy as np

from glstest import fail, look_at, ok, render_green, write

BIN, TMP = sys.argv[1], sys.argv[2]
BOUNDARY_PX = 1.5
W, H, F = 640, 480, 500.0
AMB = 0.2
ALBEDO = 230 / 255.0  # color(0.9, 0.9, 0.9) as RGBA8


def box_scene(hx):
    """A box [-hx, hx] x [0, 2] x [-1, 1]: its five visible faces."""
    return ("color(0.8, 0.3, 0.2);\nconst a = %r;\n" % hx +
            "poly { vert(-a, 0, -1); vert(a, 0, -1); vert(a, 2, -1); vert(-a, 2, -1); }\n"
            "poly { vert(-a, 0, 1); vert(a, 0, 1); vert(a, 2, 1); vert(-a, 2, 1); }\n"
            "poly { vert(-a, 0, -1); vert(-a, 0, 1); vert(-a, 2, 1); vert(-a, 2, -1); }\n"
            "poly { vert(a, 0, -1); vert(a, 0, 1); vert(a, 2, 1); vert(a, 2, -1); }\n"
            "poly { vert(-a, 2, -1); vert(a, 2, -1); vert(a, 2, 1); vert(-a, 2, 1); }\n")


def box_hit(o, d, hx):
    """Parameter t where rays o + t d first meet the box [-hx,hx]x[0,2]x[-1,1] (inf: never)."""
    lo, hi = np.array([-hx, 0.0, -1.0]), np.array([hx, 2.0, 1.0])
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - o) / d
        t2 = (hi - o) / d
    tmin = np.nanmax(np.minimum(t1, t2), axis=-1)
    tmax = np.nanmin(np.maximum(t1, t2), axis=-1)
    hit = (tmax >= np.maximum(tmin, 0))
    return np.where(hit, np.maximum(tmin, 0), np.inf)


def light_dir(incidence, azimuth_deg):
    a, b = math.radians(incidence), math.radians(azimuth_deg)
    return np.array([math.sin(a) * math.cos(b), math.cos(a), math.sin(a) * math.sin(b)])


def render_case(name, incidence, azimuth_deg, C, target, hx, shift=(0.0, 0.0, 0.0)):
    """The scene and camera, both moved by shift; the image's green channel."""
    L = light_dir(incidence, azimuth_deg)
    d = os.path.join(TMP, name)
    write(os.path.join(d, "Top.scene"),
          "trans(%r, %r, %r);\n" % tuple(shift) +
          "shadows(2048);\nambient(%r, %r, %r);\nlight(directional, %r, %r, %r, 1, 1, 1);\n" % ((AMB,) * 3 + tuple(L)) +
          "color(0.9, 0.9, 0.9);\npoly { vert(-6, 0, -6); vert(6, 0, -6); vert(6, 0, 6); vert(-6, 0, 6); }\n" + box_scene(hx))
    R, T = look_at(np.asarray(C, float), target)
    T = T - R @ np.asarray(shift, float)
    return render_green(BIN, d, R, T, (W, H, F), 100)


def case(name, incidence, azimuth_deg, C, target, hx):
    L = light_dir(incidence, azimuth_deg)
    R, T = look_at(np.asarray(C, float), target)
    img = render_case(name, incidence, azimuth_deg, C, target, hx)

    u, v = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    dirs = np.stack([(u - (W - 1) / 2) / F, (v - (H - 1) / 2) / F, np.ones_like(u)], axis=-1) @ R
    C = np.asarray(C, float)
    tp = -C[1] / dirs[..., 1]
    p = C + tp[..., None] * dirs
    on_plane = (tp > 0) & (np.abs(p[..., 0]) < 6) & (np.abs(p[..., 2]) < 6)
    tb = box_hit(np.broadcast_to(C, dirs.shape), dirs, hx)
    box = tb < np.where(on_plane, tp, np.inf)
    plane = on_plane & ~box
    shadow = np.isfinite(box_hit(p + 1e-9 * L, np.broadcast_to(L, p.shape), hx)) & plane
    lit_v = np.floor(255 * ALBEDO * (AMB + L[1]) + 0.5)
    shd_v = np.floor(255 * ALBEDO * AMB + 0.5)
    seen_shadow = img < 0.5 * (lit_v + shd_v)
    region = (shadow | box).astype(np.uint8)
    # distance (px) of every pixel to the true region's boundary
    dist = np.where(region > 0, cv2.distanceTransform(region, cv2.DIST_L2, 5),
                    cv2.distanceTransform(1 - region, cv2.DIST_L2, 5))
    # the box's silhouette and the plane's edge are the rasteriser's
    # business, not the shadow's: plane pixels within BOUNDARY_PX of a box
    # pixel or of the plane's edge are left out
    off_box = cv2.distanceTransform((1 - box).astype(np.uint8), cv2.DIST_L2, 5) > BOUNDARY_PX
    inside = cv2.distanceTransform(on_plane.astype(np.uint8), cv2.DIST_L2, 5) > BOUNDARY_PX
    plane = plane & off_box & inside
    wrong = plane & (seen_shadow != shadow)
    far_wrong = wrong & (dist > BOUNDARY_PX)
    # plane pixels away from the boundary equal the closed form within 1 level
    interior = plane & (dist > BOUNDARY_PX)
    dev = np.abs(img - np.where(shadow, shd_v, lit_v))[interior]
    return shadow, wrong, far_wrong, dev, box, plane, seen_shadow, img


# contact: 45 degrees, the shadow towards -x, seen from -x, cast by a box
# 5 cm thick: the map holds its lit face, 5 cm from the shadowed one, so
# that a depth bias beyond about 7 cm would show as a lit gap between the
# box and its shadow (a solid 2 m box would hide up to 2.8 m)
shadow, wrong, far_wrong, dev, box, plane, seen, contact_img = case("contact", 45, 0, [-9.0, 6.0, 5.0], [-1.5, 0.5, 0.0], 0.025)
k = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (7, 7))
near_box = cv2.dilate(box.astype(np.uint8), k).astype(bool) & shadow  # true shadow within 3 px of the box
gap = near_box & ~seen
print("# contact: %d shadow pixels, %d differ from the geometry (all within %.1f px of its boundary: %s); "
      "%d lit pixels in the shadow within 3 px of the box" %
      (shadow.sum(), wrong.sum(), BOUNDARY_PX, not far_wrong.any(), gap.sum()))
if shadow.sum() > 2000 and near_box.sum() > 100 and not far_wrong.any() and not gap.any() and dev.max() <= 1:
    ok("shadows_contact_boundary")
else:
    fail("shadows_contact_boundary", "%d shadow pixels, %d near the box; %d pixels wrong farther than %.1f px from "
         "the boundary; %d gap pixels at the box; interior error max %.1f levels" %
         (shadow.sum(), near_box.sum(), far_wrong.sum(), BOUNDARY_PX, gap.sum(), dev.max()))

# grazing: 80 degrees incidence, from the side; the lit plane free of acne
shadow, wrong, far_wrong, dev, box, plane, seen, _ = case("grazing", 80, 30, [0.0, 7.0, 10.0], [0.0, 0.0, 0.0], 1.0)
print("# grazing: %d plane pixels (%d in shadow); %d differ from the geometry, %d farther than %.1f px from the "
      "boundary; interior error max %.1f levels" %
      (plane.sum(), shadow.sum(), wrong.sum(), far_wrong.sum(), BOUNDARY_PX, dev.max()))
if plane.sum() > 50000 and shadow.sum() > 2000 and not far_wrong.any() and dev.max() <= 1:
    ok("shadows_grazing_no_acne")
else:
    fail("shadows_grazing_no_acne", "%d pixels wrong farther than %.1f px from the boundary; interior error max "
         "%.1f levels (<= 1)" % (far_wrong.sum(), BOUNDARY_PX, dev.max()))

# far from the origin (1e6 units, a multiple of the chunk cell): the maps
# and their matrices are composed in double, relative to the light's box
# and the camera, so the image is the same, byte for byte
far = render_case("contact_far", 45, 0, [-9.0, 6.0, 5.0], [-1.5, 0.5, 0.0], 0.025, (64.0 * 2 ** 14, 0.0, -64.0 * 2 ** 13))
if np.array_equal(far, contact_img):
    ok("shadows_far_from_origin")
else:
    fail("shadows_far_from_origin", "1e6 units away the image differs at %d pixels" % int((far != contact_img).sum()))
