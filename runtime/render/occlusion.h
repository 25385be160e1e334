/* The drawing order of a pass and occlusion culling of its draw items,
 * the GL-free half: the order (nearest instances first), which units are
 * drawn first untested (the occluders), which are tested, and the padded
 * boxes the tests draw (render.c draws them in occlusion queries).
 *
 * Exactness (spec/bundle.md 9.3, "Occlusion culling"): a unit is skipped
 * only when no sample of its padded boxes passes the depth test against
 * the depth the pass has drawn so far.  Every fragment the unit could draw
 * lies behind the boxes' front faces at that sample (they contain it with
 * a margin far above float rounding), and the pass draws every other unit
 * in the same order as without culling, so the skipped fragment could
 * never have been the nearest there, nor tied with it: the image is the
 * same, byte for byte, with and without occlusion culling.  Boxes that
 * reach the near plane are never tested (their clipped faces would leave
 * holes).
 */
#ifndef GLS_OCCLUSION_H
#define GLS_OCCLUSION_H

#include <stddef.h>
#include <stdint.h>
#include "camera.h"
#include "scene.h"

typedef enum {
    GLS_OCCLUSION_AUTO, /* test when it is likely to pay (the default: 0)   */
    GLS_OCCLUSION_ON,   /* test whenever there is something to test        */
    GLS_OCCLUSION_OFF   /* draw every item the frustum keeps               */
} gls_occlusion_mode;

/* AUTO tests only when the items the frustum keeps hold at least this many
 * vertices: below it the queries and their waits cost more than they
 * save (bench/instances_bench measures both sides). */
#define GLS_OCCLUSION_MIN_VERTS 200000u
/* The occluders: the first units of the drawing order holding up to this
 * fraction of the kept vertices, drawn before anything is tested. */
#define GLS_OCCLUSION_OCCLUDER_SHARE 0.03
/* The tested units are tested in this many rounds, in the drawing order,
 * each against everything drawn before it.  Measured on the bench's forest
 * from its edge (instances_bench forest edge 10, 3 runs each,
 * interleaved, with the test boxes and one drawing pass): 32 rounds hide
 * 5,644 of the 6,684 items at 14.4-15.0 frames/s; 64 and 128 hide 5,692
 * and 5,712 at the same rate (14.1-14.6, 13.7-14.4); 256 and 512 (rounds
 * of 4 and 2 units at least) hide 5,728 but are slower (12.1-12.5,
 * 10.6-10.9), each round waiting for its queries.  Earlier, with one box
 * per unit and a depth-only pre-pass, 16 hid fewer. */
#define GLS_OCCLUSION_ROUNDS 32u
/* Once 1/GLS_OCCLUSION_PROBE of the tested units are tested, testing
 * stops if fewer than 1 in GLS_OCCLUSION_STOP of them were hidden: the
 * rest are drawn untested (measured by make bench-instances: the forest
 * from its edge hides 12 % of them by then, its --sparse variant, the
 * same boxes around ribs, 1 %; testing on made that one twice as slow,
 * stopping there costs it about 10 %). */
#define GLS_OCCLUSION_PROBE 16u
#define GLS_OCCLUSION_STOP 16u
/* AUTO tests only scenes of many units (instances' runs of items): with
 * a few large ones, the boxes' fill costs more than they hide. */
#define GLS_OCCLUSION_MIN_UNITS 256u
/* AUTO tests only when the units' boxes cover the image this many times
 * over (their projected bounding rectangles): below it little can hide. */
#define GLS_OCCLUSION_MIN_OVERDRAW 4.0
/* AUTO tests only when the model of the geometry's own depth complexity
 * (occlusion.c overdraw: the units' triangles' areas as seen, over the
 * image's) is at least this: a scene whose triangles cover the image about
 * once has little behind what is drawn first to hide, however much its
 * boxes overlap (issue 30's 100,000 scattered triangles: boxes over the
 * image 372 times, 9,539 queries, none paying).  A model, not a
 * measurement, so that --explain says the decision before anything is
 * drawn and every run of a camera decides alike. */
#define GLS_OCCLUSION_MIN_DEPTH 2.0
/* Vertices of one box: 12 triangles. */
#define GLS_OCCLUSION_BOX_VERTS 36u
/* Vertices of the faces of one box that face the camera: at most 3. */
#define GLS_OCCLUSION_FRONT_VERTS 18u

/* Items of one instance tested together, at most (make_units). */
#define GLS_OCCLUSION_UNIT_ITEMS 8u

typedef struct {
    /* the drawing order: the kept items (indices into the scene's items)
       by the distance from the camera centre to their instance's world
       box, then by index; and its units, runs of consecutive items of
       one instance (items[unit_first .. + unit_n]), with their vertices
       and union boxes */
    uint32_t *items, nitems_in, *unit_first, *unit_n, nunits;
    uint64_t *unit_verts;
    double *unit_area;  /* its chunks' triangles' area, world units^2     */
    double *lo, *hi;    /* world box (for the overdraw and the padding)  */
    double *plo, *phi;  /* box in the instance's frame (clips the tests) */
    /* the plan, when gls_occlusion_plan returns 1 */
    uint8_t *occluder;  /* per item: 1 if in the nearest units, drawn
                           first, untested                              */
    uint8_t *utested;   /* per unit: 1 if tested before it is drawn      */
    uint32_t *tested;   /* the tested units, in the drawing order        */
    uint32_t ntested;
    uint8_t *boxes;     /* the tested units' boxes, vertices of
                           `stride` bytes: each padded box's faces that
                           face the camera, relative to the camera centre
                           (float x, y, z at offset 0), the rest white /
                           zero, so the scene's own attribute pointers
                           can read them                                */
    uint32_t *box_first, *box_n; /* per tested unit: its vertices there */
    uint32_t box_verts;          /* all of them                          */
    /* why: the plan's figures (gls_occlusion_plan fills them in even when
       it returns 0 because AUTO finds too little to gain) */
    double overdraw;
    double depth;       /* the model of the geometry's depth complexity  */
    uint64_t total_verts;
    /* scratch */
    double *key;
    size_t cap, box_cap;
} gls_occlusion;

/* The drawing order of a colour pass of camera c (centre C) over the
 * items vis keeps (NULL: all), and its occlusion plan: 1 when there are
 * units to test, 0 when every unit is drawn untested (mode OFF, too
 * little to gain, nothing to test), -1 when out of memory (then there
 * is no order either).  The order depends only on C, the scene and
 * which items are kept, so every pass of a camera (colour, ids, flow)
 * resolves exact depth ties alike, with occlusion culling or without. */
int gls_occlusion_plan(gls_occlusion *o, gls_occlusion_mode mode, const gls_scene *s, const gls_camera *c,
                       const double C[3], const uint8_t *vis);

/* The padded box tested for geometry within box plo..phi of an
 * instance's frame, W its world transform (row-major, affine), wlo..whi
 * its world box: the box plo..phi under W (an oriented box, tighter than
 * the world one for a turned instance; the world box when W is singular
 * or NULL), each face moved out by the margin, relative to C, as 8
 * corners (bit 0: x, bit 1: y, bit 2: z high).  0, or -1 when any
 * corner is not in front of the near plane (or not finite): never tested. */
int gls_occlusion_box(const gls_camera *c, const double C[3], const double W[16], const double plo[3],
                      const double phi[3], const double wlo[3], const double whi[3], double corner[8][3]);

/* Which faces of the box by its corners (gls_occlusion_box's, relative to
 * the camera centre) face the camera: front[f] = 1 for those, in the
 * order z low, z high, y low, y high, x low, x high (of the corners' bit
 * order); how many (at most 3).  Only those are drawn in a query: the
 * camera is outside the box (every corner is in front of the near
 * plane), so a ray meets a front face of the box before any back face,
 * and wherever a back face would pass the depth test, the front face
 * nearer on the same ray passes too. */
int gls_occlusion_faces(const double corner[8][3], uint8_t front[6]);

void gls_occlusion_free(gls_occlusion *o);

#endif
