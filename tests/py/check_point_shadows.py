"""Shadows of point lights (issue 16, spec/camera.md "Shadows"): a plane
lit by a point light (no attenuation) with shadows(2048) and an occluder,
rendered by glsplay and checked against the geometry computed here in
numpy.  The shadow of an occluder on the plane is the central projection
of its outline from the light:

- edges: a horizontal square above the plane; on every image row that
  crosses a steep edge of the projected outline (the square's corners
  scaled about the light onto the plane, then through the camera), the
  rendered edge (where the intensity crosses halfway between the closed-
  form lit and shadowed values, interpolated between pixels) lies within
  EDGE_PX of the outline; every plane pixel whose state (lit or shadowed)
  differs from the geometry lies within BOUNDARY_PX of the true
  boundary, and every pixel farther than that equals the closed form
  255 a (ambient + max(0, n . l)) or 255 a ambient within 1 level;
- seam: the square spans the edge between two cube faces (-Y and +X), so
  its shadow does too: the same checks (a crack would be a lit line inside
  the shadow, a double shadow a dark one outside it);
- grazing: a light 0.8 above a 10 x 10 plane, lit at up to 83.5 degrees
  incidence (tan 8.8, within the bias's cap of tan 10), with a box
  standing on it: no acne (the same checks);
- contact: a box 5 cm thick standing on the plane, seen from its shadow's
  side: the same checks, and no lit pixel of the true shadow within 3 px
  of the box (no peter-panning gap);
- with a sun: the edges scene lit by the point light and a directional
  light, each casting its own shadow: within 1 level of the closed form
  away from both boundaries (the maps of mixed kinds each at its light);
- off: the edges scene without shadows(...) equals the closed form with no
  shadow at all, and outside the true shadow (and its boundary) the image
  with shadows equals it byte for byte;
- far from the origin: the seam case moved 1e6 units with its camera
  gives the same image, byte for byte.

Usage: check_point_shadows.py BIN TMPDIR.  Prints "ok NAME" / "FAIL NAME: why"."""
import os
import sys

import cv2
import numpy as np

from glstest import fail, look_at, ok, render_green, write

BIN, TMP = sys.argv[1], sys.argv[2]
BOUNDARY_PX = 1.5
EDGE_PX = 1.5
W, H, F = 640, 480, 500.0
AMB = 0.2
ALBEDO = 230 / 255.0  # color(0.9, 0.9, 0.9) as RGBA8


def box_text(lo, hi):
    """The six faces of the box lo..hi."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    q = lambda *p: "poly { " + " ".join("vert(%r, %r, %r);" % v for v in p) + " }\n"
    return (q((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)) +
            q((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)) +
            q((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)) +
            q((x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0)) +
            q((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)) +
            q((x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)))


def box_hit(o, d, lo, hi):
    """Parameter t where rays o + t d first meet the box lo..hi (inf: never)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - o) / d
        t2 = (hi - o) / d
    tmin = np.nanmax(np.minimum(t1, t2), axis=-1)
    tmax = np.nanmin(np.maximum(t1, t2), axis=-1)
    hit = tmax >= np.maximum(tmin, 0)
    return np.where(hit, np.maximum(tmin, 0), np.inf)


def render(name, L, half, box, C, target, shadows=True, shift=(0.0, 0.0, 0.0), lights=None):
    """Plane y = 0, |x|, |z| < half, a point light at L (or the lights
    given), the box (lo, hi); scene and camera moved by shift.  The image's
    green channel."""
    d = os.path.join(TMP, name)
    write(os.path.join(d, "Top.scene"),
          "trans(%r, %r, %r);\n" % tuple(shift) + ("shadows(2048);\n" if shadows else "") +
          "ambient(%r, %r, %r);\n" % ((AMB,) * 3) + (lights or "light(point, %r, %r, %r, 1, 1, 1);\n" % tuple(L)) +
          "color(0.9, 0.9, 0.9);\npoly { vert(-%r, 0, -%r); vert(%r, 0, -%r); vert(%r, 0, %r); vert(-%r, 0, %r); }\n"
          % ((half,) * 8) + "color(0.8, 0.3, 0.2);\n" + box_text(*box))
    R, T = look_at(np.asarray(C, float), target)
    T = T - R @ np.asarray(shift, float)
    return render_green(BIN, d, R, T, (W, H, F), 200)


def geometry(L, half, box, C, target):
    """Per pixel: the plane's closed-form lit and shadowed values, the true
    shadow, the occluder's and the plane's masks, the distance to the true
    boundary."""
    L, C = np.asarray(L, float), np.asarray(C, float)
    R, _ = look_at(C, target)
    u, v = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    dirs = np.stack([(u - (W - 1) / 2) / F, (v - (H - 1) / 2) / F, np.ones_like(u)], axis=-1) @ R
    tp = -C[1] / dirs[..., 1]
    p = C + tp[..., None] * dirs
    on_plane = (tp > 0) & (np.abs(p[..., 0]) < half) & (np.abs(p[..., 2]) < half)
    box_px = box_hit(np.broadcast_to(C, dirs.shape), dirs, *box) < np.where(on_plane, tp, np.inf)
    plane = on_plane & ~box_px
    to_l = L - p
    dist_l = np.linalg.norm(to_l, axis=-1)
    shadow = (box_hit(p, to_l, *box) < 1.0) & plane  # the segment from p to the light meets the box
    nl = np.maximum(to_l[..., 1] / dist_l, 0)
    lit_v = np.minimum(np.floor(255 * ALBEDO * (AMB + nl) + 0.5), 255)  # a sum above 1 saturates
    shd_v = np.full_like(lit_v, np.floor(255 * ALBEDO * AMB + 0.5))
    region = (shadow | box_px).astype(np.uint8)
    dist = np.where(region > 0, cv2.distanceTransform(region, cv2.DIST_L2, 5),
                    cv2.distanceTransform(1 - region, cv2.DIST_L2, 5))
    # the box's silhouette and the plane's edge are the rasteriser's
    # business, not the shadow's: pixels within BOUNDARY_PX of them are left out
    off_box = cv2.distanceTransform((1 - box_px).astype(np.uint8), cv2.DIST_L2, 5) > BOUNDARY_PX
    inside = cv2.distanceTransform(on_plane.astype(np.uint8), cv2.DIST_L2, 5) > BOUNDARY_PX
    return dict(R=R, lit=lit_v, shd=shd_v, shadow=shadow, box=box_px, plane=plane & off_box & inside, dist=dist,
                p=p, nl=nl)


def pixel_checks(g, img):
    """Pixels in the wrong state farther than BOUNDARY_PX from the true
    boundary; the largest deviation from the closed form there."""
    seen = img < 0.5 * (g["lit"] + g["shd"])
    wrong = g["plane"] & (seen != g["shadow"])
    far_wrong = wrong & (g["dist"] > BOUNDARY_PX)
    interior = g["plane"] & (g["dist"] > BOUNDARY_PX)
    dev = np.abs(img - np.where(g["shadow"], g["shd"], g["lit"]))[interior]
    return int(far_wrong.sum()), float(dev.max()), seen


def outline_edges(g, img, L, C, corners):
    """Row by row: the shadow outline (corners of a horizontal square at
    height h, projected from the light onto y = 0, then into the image)
    against the rendered edge; the errors in px of every steep edge's
    crossing more than 2 px from a corner's row, away from the box."""
    L, C = np.asarray(L, float), np.asarray(C, float)
    R = g["R"]
    img_pts = []
    for q in corners:
        q = np.asarray(q, float)
        s = L + (q - L) * (L[1] / (L[1] - q[1]))  # central projection onto the plane
        pc = R @ (s - C)
        img_pts.append((F * pc[0] / pc[2] + (W - 1) / 2, F * pc[1] / pc[2] + (H - 1) / 2))
    frac = (img - g["shd"]) / np.maximum(g["lit"] - g["shd"], 1)
    errs = []
    for k in range(len(img_pts)):
        (ua, va), (ub, vb) = img_pts[k], img_pts[(k + 1) % len(img_pts)]
        if abs(vb - va) < 0.5 * abs(ub - ua):
            continue  # a shallow edge: rows do not cross it cleanly
        for row in range(int(np.ceil(min(va, vb) + 2)), int(np.floor(max(va, vb) - 2)) + 1):
            ut = ua + (row - va) * (ub - ua) / (vb - va)
            c0, c1 = int(np.floor(ut)) - 4, int(np.floor(ut)) + 5
            if c0 < 0 or c1 >= W or not g["plane"][row, c0:c1 + 1].all():
                continue
            f = frac[row, c0:c1 + 1]
            cross = [c0 + i + (0.5 - f[i]) / (f[i + 1] - f[i]) for i in range(len(f) - 1)
                     if (f[i] - 0.5) * (f[i + 1] - 0.5) < 0 or f[i] == 0.5]
            errs.append(min(abs(x - ut) for x in cross) if cross else np.inf)
    return np.array(errs)


def edges_case(name, L, square, C, target, half=6.0):
    """A horizontal square (x0, x1, h, z0, z1) above the plane."""
    x0, x1, h, z0, z1 = square
    box = ((x0, h, z0), (x1, h, z1))
    img = render(name, L, half, box, C, target)
    g = geometry(L, half, box, C, target)
    far_wrong, dev, _ = pixel_checks(g, img)
    errs = outline_edges(g, img, L, C, [(x0, h, z0), (x1, h, z0), (x1, h, z1), (x0, h, z1)])
    print("# %s: %d shadow pixels; %d rows of edges, error max %.2f px, mean %.2f px; %d pixels wrong farther than "
          "%.1f px from the boundary; interior error max %.1f levels" %
          (name, g["shadow"].sum(), len(errs), errs.max(), errs.mean(), far_wrong, BOUNDARY_PX, dev))
    good = g["shadow"].sum() > 2000 and len(errs) > 100 and errs.max() <= EDGE_PX and far_wrong == 0 and dev <= 1
    why = "%d rows, edge error max %.2f px (<= %.1f); %d pixels wrong farther than %.1f px; interior max %.1f levels" % (
        len(errs), errs.max(), EDGE_PX, far_wrong, BOUNDARY_PX, dev)
    return good, why, img, g


# edges: the square 1 x 1 at height 2 under the light at height 4: a 2 x 2 shadow
EDGES = ((0.0, 4.0, 0.0), (0.5, 1.5, 2.0, 0.0, 1.0), (0.0, 9.0, 7.0), (1.0, 0.0, 0.5))
good, why, edges_img, edges_g = edges_case("edges", *EDGES)
(ok if good else lambda n: fail(n, why))("point_shadow_edges")

# seam: the light at (0, 2, 0), the square over x = 1 at height 1 and its
# shadow over x = 2: both cross the plane |x| = |y| between faces -Y and +X
# (off centre in z, so that a face mirrored in z would show)
SEAM = ((0.0, 2.0, 0.0), (0.6, 1.4, 1.0, -0.2, 0.6), (2.0, 4.5, 4.0), (2.0, 0.0, 0.0))
good, why, seam_img, _ = edges_case("seam", *SEAM)
(ok if good else lambda n: fail(n, why))("point_shadow_seam")

# grazing: the light 0.8 above the plane, the plane out to 5 (83.5 degrees
# at its corners, where the faces +-X and +-Z see it edge on)
L = (0.0, 0.8, 0.0)
box = ((1.5, 0.0, -0.25), (2.0, 0.4, 0.25))
C, tgt = (-1.0, 5.0, 8.0), (1.0, 0.0, 0.0)
img = render("grazing", L, 5.0, box, C, tgt)
g = geometry(L, 5.0, box, C, tgt)
far_wrong, dev, _ = pixel_checks(g, img)
print("# grazing: %d plane pixels (%d in shadow); %d wrong farther than %.1f px from the boundary; interior error "
      "max %.1f levels" % (g["plane"].sum(), g["shadow"].sum(), far_wrong, BOUNDARY_PX, dev))
if g["plane"].sum() > 50000 and g["shadow"].sum() > 2000 and far_wrong == 0 and dev <= 1:
    ok("point_shadow_grazing_no_acne")
else:
    fail("point_shadow_grazing_no_acne", "%d pixels wrong farther than %.1f px from the boundary; interior error max "
         "%.1f levels (<= 1)" % (far_wrong, BOUNDARY_PX, dev))

# contact: a box 5 cm thick standing on the plane, its face towards the
# light at 45 degrees incidence at its foot, seen from the shadow's side
L = (0.0, 3.0, 0.0)
box = ((3.0, 0.0, -0.75), (3.05, 1.5, 0.75))
C, tgt = (9.0, 4.0, 4.0), (4.0, 0.0, 0.0)
img = render("contact", L, 8.0, box, C, tgt)
g = geometry(L, 8.0, box, C, tgt)
far_wrong, dev, seen = pixel_checks(g, img)
near_box = cv2.dilate(g["box"].astype(np.uint8), cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (7, 7))).astype(bool)
near_box &= g["shadow"]
gap = near_box & ~seen
print("# contact: %d shadow pixels, %d of them within 3 px of the box; %d lit there; %d wrong farther than %.1f px "
      "from the boundary; interior error max %.1f levels" %
      (g["shadow"].sum(), near_box.sum(), gap.sum(), far_wrong, BOUNDARY_PX, dev))
if g["shadow"].sum() > 2000 and near_box.sum() > 100 and not gap.any() and far_wrong == 0 and dev <= 1:
    ok("point_shadow_contact")
else:
    fail("point_shadow_contact", "%d gap pixels at the box; %d pixels wrong farther than %.1f px; interior max %.1f "
         "levels" % (gap.sum(), far_wrong, BOUNDARY_PX, dev))

# with a sun: the point light first (slot 0, a cube map on unit 9) and a
# directional light second (slot 1, a 2D map on unit 2), half as bright
# each: every plane pixel more than BOUNDARY_PX from both shadows'
# boundaries within 1 level of 255 a (ambient + sum of the unshadowed
# lights' 0.5 max(0, n . l))
LD = np.array([0.5, 1.0, -0.3]) / np.linalg.norm([0.5, 1.0, -0.3])
x0, x1, h, z0, z1 = EDGES[1]
box = ((x0, h, z0), (x1, h, z1))
sun = render("sun", EDGES[0], 6.0, box, EDGES[2], EDGES[3],
             lights="light(point, %r, %r, %r, 0.5, 0.5, 0.5);\nlight(directional, %r, %r, %r, 0.5, 0.5, 0.5);\n" %
             (tuple(EDGES[0]) + tuple(LD)))
g = geometry(EDGES[0], 6.0, box, EDGES[2], EDGES[3])
shadow_d = np.isfinite(box_hit(g["p"] + 1e-9 * LD, np.broadcast_to(LD, g["p"].shape), *box)) & g["plane"]
want = np.minimum(np.floor(255 * ALBEDO * (AMB + 0.5 * g["nl"] * ~g["shadow"] + 0.5 * LD[1] * ~shadow_d) + 0.5), 255)
region_d = (shadow_d | g["box"]).astype(np.uint8)
dist_d = np.where(region_d > 0, cv2.distanceTransform(region_d, cv2.DIST_L2, 5),
                  cv2.distanceTransform(1 - region_d, cv2.DIST_L2, 5))
interior = g["plane"] & (g["dist"] > BOUNDARY_PX) & (dist_d > BOUNDARY_PX)
dev = float(np.abs(sun - want)[interior].max())
print("# sun: %d pixels in the point light's shadow, %d in the sun's; interior error max %.1f levels" %
      ((g["shadow"] & interior).sum(), (shadow_d & interior).sum(), dev))
if (g["shadow"] & interior).sum() > 2000 and (shadow_d & interior).sum() > 1000 and dev <= 1:
    ok("point_shadow_with_sun")
else:
    fail("point_shadow_with_sun", "interior error max %.1f levels (<= 1)" % dev)

# off: no shadows(...): no shadow at all, and the shadowed image equals it
# outside the true shadow
x0, x1, h, z0, z1 = EDGES[1]
off = render("off", EDGES[0], 6.0, ((x0, h, z0), (x1, h, z1)), EDGES[2], EDGES[3], shadows=False)
g = dict(edges_g, shadow=np.zeros_like(edges_g["shadow"]))
interior = edges_g["plane"]
dev = float(np.abs(off - edges_g["lit"])[interior].max())
outside = edges_g["plane"] & ~edges_g["shadow"] & (edges_g["dist"] > BOUNDARY_PX)
same = int((off != edges_img)[outside].sum())
print("# off: plane error max %.1f levels against the unshadowed closed form; %d pixels outside the shadow differ "
      "from the shadowed image" % (dev, same))
if dev <= 1 and same == 0 and outside.sum() > 50000:
    ok("point_shadow_off")
else:
    fail("point_shadow_off", "plane error max %.1f levels (<= 1); %d pixels outside the shadow differ" % (dev, same))

# far from the origin (1e6 units, a multiple of the chunk cell)
x0, x1, h, z0, z1 = SEAM[1]
far = render("seam_far", SEAM[0], 6.0, ((x0, h, z0), (x1, h, z1)), SEAM[2], SEAM[3],
             shift=(64.0 * 2 ** 14, 0.0, -64.0 * 2 ** 13))
if np.array_equal(far, seam_img):
    ok("point_shadow_far_from_origin")
else:
    fail("point_shadow_far_from_origin", "1e6 units away the image differs at %d pixels" % int((far != seam_img).sum()))
