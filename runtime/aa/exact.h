/* Exact coverage (spec/antialiasing.md "Exact coverage", issue 28): every
 * pixel the exact area of what is visible in it, for triangles, in double,
 * with no sampling and no GL.
 *
 * Coordinates are the camera model's image coordinates (spec/camera.md):
 * pixel centres at integers, so pixel (i, j) is the square
 * [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5].  Each triangle carries 1/Zc at
 * its vertices; for a planar triangle under a pinhole 1/Zc is affine in
 * image coordinates, so the plane through the three values is its depth
 * everywhere and two triangles' equal-depth line is straight.
 *
 * Method (Catmull 1978, with the area arithmetic of font rasterisers):
 * the pixels no edge crosses take the one surface that covers them; in a
 * pixel an edge crosses, each candidate triangle is clipped against the
 * pixel square in pixel-local coordinates and every other candidate that is
 * nearer over part of it is cut away (its triangle intersected with the
 * half-plane where it is nearer), leaving disjoint convex pieces whose
 * areas are exact up to rounding.  Shared edges are clipped with one
 * canonical orientation, so neighbours cancel (exact_int.h).  The files:
 * exact_poly.c the convex polygon arithmetic, exact_pixels.c the pixels
 * and their candidates, exact_image.c colour, exact_project.c the 3-D
 * triangle to image triangles. */
#ifndef GLS_EXACT_H
#define GLS_EXACT_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double x[3], y[3];  /* image position of the vertices (pixel centres at
                           integers)                                      */
    double iz[3];       /* 1/Zc at the vertices, > 0; larger is nearer     */
    uint32_t id;        /* the surface's id, reported with its coverage    */
    float rgba[4];      /* flat colour (gls_exact_image without a shader) */
    uint8_t flags;      /* GLS_EXACT_SAMPLED, GLS_EXACT_HOLES             */
} gls_exact_tri;

/* Its shaded colour is not affine in the image (texture, lighting): a
 * region's colour is the mean of the shader at the GLS_EXACT_SHADE_M
 * lattice points of the pixel that fall in the region
 * (gls_exact_shade_fn). */
#define GLS_EXACT_SAMPLED 1u
/* Alpha-tested (GL discards where the shader's alpha is under 0.5): it
 * hides nothing in the walk, and a pixel it shows in is point-sampled at
 * the GLS_EXACT_SHADE_M lattice points, each the nearest surface there
 * whose alpha passes.  No area is computed there (the frags are the
 * pixel's candidates, area NaN): gls_exact_image only, not coverage. */
#define GLS_EXACT_HOLES 2u

/* The lattice points (lattice.h) per pixel at which a sampled triangle's
 * colour is averaged over a region: texture edges and highlights inside
 * a region are sampled at these, its area stays exact. */
#define GLS_EXACT_SHADE_M 64

/* What one triangle shows in one pixel: the exact area (pixel units, the
 * square is 1) of the part of it that is visible, and that part's
 * centroid in image coordinates (the pixel centre where area is 0). */
typedef struct {
    size_t tri;         /* index into the caller's triangles              */
    double area;
    double cx, cy;
} gls_exact_frag;

/* Called once for every pixel of the image, rows top to bottom, with the
 * triangles visible in it (n 0: none; the areas sum to at most 1, the
 * rest is background).  Where an alpha-tested triangle (GLS_EXACT_HOLES)
 * has a visible part, the pixel is point-sampled and its frags are its
 * candidates instead: every triangle that may show in it, a hidden one
 * included, each with area NaN and the pixel centre for centroid (no
 * area is worked out: the cuts of every layer behind a tree's leaves were
 * a third of the road frame's CPU, for areas nothing used).  The frags
 * are valid during the call only. */
typedef void (*gls_exact_pixel_fn)(void *user, int px, int py, const gls_exact_frag *f, size_t n);

/* Visit the w x h image.  Ties (coplanar overlapping triangles): the lower
 * index is in front.  Triangles of zero image area are skipped.  The bands
 * of rows are worked out on one thread per online CPU, fn called on the
 * calling thread, in order; memory is bounded by two bands of rows a
 * thread and the candidates in them.  Returns 0, or -1 when out of memory
 * (fn may have been called for part of the image) or given 2^32
 * triangles or more, or an image 2^27 pixels wide or more. */
int gls_exact_visit(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user);
/* The same on threads worker threads (0: one per online CPU, 1: none, on
 * the calling thread only); the frags are the same for any number. */
int gls_exact_visit_threads(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user,
                            unsigned threads);
/* gls_exact_visit with fn called on the worker threads, a band's pixels
 * in order but the bands in any order and side by side: for an fn whose
 * result for a pixel depends on that pixel's frags only and that writes
 * nothing another pixel's call reads (the image's values: the pixel work
 * is then spread over the cores too, not done on one thread while the
 * others wait for it). */
int gls_exact_visit_any_thread(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user);

/* A region's colour: the colour of triangle t (index i) at image point
 * (x, y), the centroid of what is visible of it in a pixel.  For colour
 * affine in the image (flat, or interpolated linearly in screen space)
 * that is the region's exact mean.  A sampled triangle's (t->sampled)
 * region takes the mean of the calls at the pixel's lattice points in it
 * instead, the centroid's when none is.  The shader takes n points of one
 * triangle at once, (x[p], y[p]) into rgba[p] (a pixel's lattice points
 * in one region: what depends on the triangle only is looked up once).
 * gls_exact_image and gls_exact_render call it from worker threads, side
 * by side: it must only read what user points to. */
typedef void (*gls_exact_shade_fn)(void *user, const gls_exact_tri *t, size_t i, const double *x, const double *y,
                                   size_t n, float (*rgba)[4]);

/* The box-filtered image: rgba (w * h * 4 floats, row 0 at the top) =
 * sum over each pixel's frags of area * colour(centroid) + (1 - sum of
 * areas) * bg.  shade NULL: each triangle's flat rgba.  0, or -1 when out
 * of memory. */
int gls_exact_image(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                    void *user, float *rgba);

/* Coverage (spec/outputs.md "Coverage"): per pixel the exact visible
 * area of each id, the GLS_EXACT_COVER_K largest, largest first (ties:
 * the smaller id), the unused slots id 0 area 0; ids 0 are not counted
 * (the background's). */
#define GLS_EXACT_COVER_K 4
typedef struct {
    uint32_t id;
    float area;
} gls_exact_cover;

/* gls_exact_image (rgba NULL: no colour) that also writes cover (NULL:
 * none; w * h * GLS_EXACT_COVER_K entries), each triangle's id mapped
 * through idmap (NULL: the id as it is).  dense: 0, every pixel exact; or
 * a pixel where more than dense triangles may show is point-sampled at
 * the GLS_EXACT_SHADE_M lattice points, as an alpha-tested one is (the
 * nearest surface at each point): resolving a pixel exactly costs about
 * the square of its candidates (a fan of 65,534 triangles drawn into a
 * 10-pixel disc took 29 s at 32 x 32).  Not with cover (its areas).
 * glsplay's default (--aa auto) bounds it at GLS_EXACT_AUTO_DENSE; --aa
 * exact does not. */
#define GLS_EXACT_AUTO_DENSE 256
int gls_exact_render(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                     void *user, const uint16_t *idmap, float *rgba, gls_exact_cover *cover, size_t dense);

/* Edge segments (spec/outputs.md "Edge segments"): the visible edges of
 * the image, from the same visibility as the areas (depth planes, ties to
 * the lower index).  One segment is a maximal piece, inside one pixel's
 * square, of a triangle edge or of two triangles' equal-depth line along
 * which the surface in front on each side stays the same and the two
 * ids differ; it runs from the line's lexicographically first end (x,
 * then y) to the other, left and right as seen walking along it in the
 * image (y down), id 0 the background.  Pieces on the image's border are
 * left out; a piece on the border of two pixels is the right or lower
 * pixel's. */
typedef struct {
    double x0, y0, x1, y1;
    uint32_t left, right;
} gls_exact_seg;
typedef void (*gls_exact_seg_fn)(void *user, const gls_exact_seg *s);

/* Visit the w x h image's segments, pixel by pixel, rows top to bottom,
 * each triangle's id mapped through idmap (NULL: as it is).  0, or -1 when
 * out of memory. */
int gls_exact_edges(const gls_exact_tri *t, size_t n, int w, int h, const uint16_t *idmap, gls_exact_seg_fn fn,
                    void *user);

/* A pinhole camera (spec/camera.md "Conventions"): world to camera
 * Pc = R (Pw - C), the camera looks along +Z, x right, y down; then
 * u = (fx Xc + skew Yc) / Zc + cx, v = fy Yc / Zc + cy.  All double: a
 * scene far from the origin loses nothing before the subtraction of C. */
typedef struct {
    double R[9];        /* row-major                                        */
    double C[3];        /* camera centre in world coordinates               */
    double fx, fy, cx, cy, skew;
    double znear;       /* > 0: triangles are clipped at Zc = znear in 3-D  */
    double zfar;        /* > znear: and at Zc = zfar (as GL clips); 0: not */
} gls_exact_pinhole;

/* World triangle p (3 points) to image triangles, clipped at the near
 * (and far) plane before projecting: writes 0 to 3 triangles to out (id
 * and rgba copied from proto) and returns how many. */
int gls_exact_project(const gls_exact_pinhole *cam, const double p[3][3], const gls_exact_tri *proto,
                      gls_exact_tri out[3]);

#endif
