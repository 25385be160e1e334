/* The frame plan: what one camera frame needs, decided once
 * (docs/ARCHITECTURE.md "The frame plan").  From the outputs asked for,
 * the anti-aliasing plan, the camera (lens, sensor, exposure effects) and
 * whether the frame has a next row (flow), gls_frame_plan_make decides
 * which passes run, which buffers they fill and how large, where the
 * image comes from, and which files go to the writer.  The player runs
 * the plan (play_frame.c), --explain prints it (explain.c) and never decides
 * anything again, the out-of-memory message sums its buffers, and the
 * frame record keys on it (frame_record.c).
 *
 * In the spirit of Blender Cycles' pass descriptors and of gallium's
 * split between the state a frontend builds and what a driver executes:
 * passes and buffers are table rows (GLS_PASSES, GLS_FRAME_BUFFERS) with
 * what each draws or holds, and the plan is plain data. */
#ifndef GLS_FRAME_PLAN_H
#define GLS_FRAME_PLAN_H

#include <stdint.h>
#include <stdio.h>
#include "aa.h"
#include "camera.h"
#include "exposure.h"
#include "output_table.h"

/* The passes a camera frame can run: X(ID, word, what it draws and makes). */
#define GLS_PASSES(X)                                                                                               \
    X(CENTRE, "centre", "one unjittered pass at the pixel centres: colour (RGBA8) and/or depth (float32)")         \
    X(TRUTH, "truth", "the ground-truth pass at the pixel centres: instance ids, normals, the depth flow starts "  \
                      "from")                                                                                       \
    X(SAMPLES, "samples", "the anti-aliasing samples, summed into the accumulator")                                 \
    X(EXACT, "exact", "exact coverage (--aa exact): the triangles projected in double on the CPU, each pixel the "  \
                      "exact visible areas times their colours, no samples")                                        \
    X(EXPOSURE, "exposure", "the samples at each sub-frame time, lens point and band of rows (motion blur, "        \
                            "rolling shutter, depth of field); with a rolling shutter the centre and truth passes " \
                            "too run once per band of rows, the bands chosen per frame from the scene's motion")   \
    X(LENS, "lens", "an undistorted fine image, read through the lens model at each pixel centre's ray")           \
    X(FLOW_NEXT, "flow", "the depth of frame t+1 with its poses (flow)")                                            \
    X(BOXES_ALONE, "boxes", "each visible instance drawn alone (the boxes' occlusion)")

enum {
#define X(id, word, what) GLS_PASS_I_##id,
    GLS_PASSES(X)
#undef X
        GLS_PASS_COUNT
};
enum {
#define X(id, word, what) GLS_PASS_##id = 1u << GLS_PASS_I_##id,
    GLS_PASSES(X)
#undef X
};

/* The buffers of one camera frame the player allocates, X(ID, word, what
 * it holds); their sizes are the plan's (gls_frame_plan.bytes).  The
 * fine framebuffer's tiles and a lens's undistorted images are bounded by
 * --aa-memory and told apart by --explain; the writer's encoded files are
 * the ENCODE row, an estimate of the largest. */
#define GLS_FRAME_BUFFERS(X)                                                                          \
    X(RGBA, "colour", "the centre pass's colour, RGBA8")                                              \
    X(DEPTH, "depth", "the centre pass's depth, float32")                                             \
    X(IDS, "ids", "the ground-truth pass's instance ids, uint32")                                     \
    X(NORMALS, "normals", "the ground-truth pass's normals, 3 x float32")                             \
    X(TRUTH_DEPTH, "truth depth", "the ground-truth pass's depth flow starts from, float32")           \
    X(ACCUM, "accumulator", "the anti-aliasing sums, 4 channels")                                     \
    X(EXACT, "exact colour", "exact coverage's image, RGBA float32")                                  \
    X(COVER, "coverage", "exact coverage's areas per instance, 4 x (id, float32)")                    \
    X(MIXED, "mixed", "each pixel's first sample and whether its samples differ (edges)")             \
    X(IMAGE, "image", "the image in its file's format")                                               \
    X(LINEAR, "linear", "the linear intensities the sensor effects work on, 3 x float32")             \
    X(EDGES, "edges", "the map of mixed pixels, 8-bit")                                               \
    X(FLOW, "flow", "flow u and v, 2 x float32, its mask, and the depth of frame t+1")                \
    X(DISPARITY, "disparity", "fx B / Zc, float32, made by the writer")                               \
    X(CODES16, "16-bit codes", "disparity16's or depth16's 16-bit codes, made by the writer")         \
    X(ENCODE, "encoding", "the largest file while it is encoded")

enum {
#define X(id, word, what) GLS_BUF_##id,
    GLS_FRAME_BUFFERS(X)
#undef X
        GLS_BUF_COUNT
};

/* Where the image file's pixels come from. */
typedef enum {
    GLS_IMAGE_NONE = 0,   /* no image output                                 */
    GLS_IMAGE_CENTRE,     /* the centre pass's RGBA8, written as it is       */
    GLS_IMAGE_CONVERTED,  /* the centre pass or the accumulator, converted to
                             the file's format (16-bit, float, RGBA8)       */
    GLS_IMAGE_SENSOR      /* through the camera's sensor effects (sensor.h)  */
} gls_image_source;

/* What decides the plan: the run's outputs and formats, the
 * anti-aliasing plan, and whether the scene or the camera moves (a
 * trajectory or a motion: shutter and line_delay act). */
typedef struct {
    unsigned outputs;              /* GLS_OUT_* asked for                 */
    gls_image_format image_format;
    const gls_aa_plan *aa;
    int moving;
} gls_plan_inputs;

typedef struct {
    unsigned outputs;      /* the files this frame writes: flow only with a
                              next row                                     */
    unsigned passes;       /* GLS_PASS_* that run                          */
    gls_exposure ex;       /* motion blur, rolling shutter, depth of field  */
    int effects;           /* exposure effects act on the image             */
    int aa;                /* the image comes from the accumulator          */
    int exact;             /* the image or the coverage comes from exact
                              coverage                                     */
    int cover;             /* exact coverage's areas per instance           */
    int segs;              /* exact coverage's edge segments                */
    int lens;              /* drawn undistorted and read through the lens   */
    int weighted;          /* the accumulator's weights (Gaussian): 64-bit  */
    int fine;              /* the samples are one fine framebuffer's pixels */
    /* what the centre and ground-truth passes read back */
    int rgba, z, ids, normals, truth_z;
    int flow, boxes;       /* flow and boxes are computed this frame        */
    int gl;                /* the frame needs GL: a pass other than exact
                              coverage's, a lens or a rolling shutter (their
                              set-up reads the renderer); exact coverage
                              alone runs on the CPU, and a run whose frames
                              need none creates no GL context (player.c)   */
    gls_image_source image;
    uint64_t bytes[GLS_BUF_COUNT]; /* each buffer's size; 0: not needed    */
    uint64_t total;        /* their sum                                     */
} gls_frame_plan;

/* Plan camera c's frame; has_next: the trajectory has a row after this
 * frame (flow is written only then). */
void gls_frame_plan_make(gls_frame_plan *fp, const gls_plan_inputs *in, const gls_camera *c, int has_next);

/* The words and descriptions of the tables. */
extern const char *const gls_pass_word[GLS_PASS_COUNT];
extern const char *const gls_pass_what[GLS_PASS_COUNT];
extern const char *const gls_buffer_word[GLS_BUF_COUNT];

/* --explain: the plan of one camera frame, a line for its passes, one
 * for its accumulator and one for its buffers:
 *   "  frame plan: passes centre truth samples"
 *   "  accumulator: 4 samples per pixel" / "  accumulator: none"
 *   "  buffers: colour 1.2 MiB, depth 1.2 MiB, ...; 3.6 MiB in all (3774873
 *   bytes, 1258291 of them the writer's)": the writer's are its estimates of
 *   disparity, 16-bit codes and the file being encoded */
void gls_frame_plan_explain(FILE *out, const gls_frame_plan *fp, const gls_aa_plan *aa);

/* What a run did, counted as it ran (tests compare it with the plan:
 * tests/unit/test_plan_matrix.c).  passes[k]: times pass k ran in the
 * last camera frame; buffers[k]: the bytes of buffer k it allocated;
 * accum_samples: the samples per pixel its accumulator summed (0: none). */
typedef struct {
    uint64_t frames;
    uint64_t passes[GLS_PASS_COUNT];
    uint64_t bytes[GLS_BUF_COUNT];
    uint64_t accum_samples;
} gls_frame_counts;

#endif
