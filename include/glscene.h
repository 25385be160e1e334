/* libglscene: the glscene renderer as a C library (docs/api.md).
 *
 * Open a compiled bundle (.glsb), set cameras from camera files or from
 * numbers, render frames into buffers the caller owns (image, depth,
 * instance ids, normals), move named instances, close.  The only public
 * header: nothing else is installed.
 *
 * Errors come back as values: a function that can fail returns NULL or
 * -1 and, when e is not NULL, writes one line saying why into e->message
 * (the same words glsplay and glsc print after "tool: error: ", or the
 * located "file:line:col: error: ..." of a camera file, with its source
 * line and caret).  The library never prints, never exits.
 *
 * Threads and GL: a player owns its GL context (glscene_open creates it
 * and makes it current on the calling thread).  Use a player only from
 * the thread that opened it (an EGL context current on one thread cannot
 * be made current on another); players of different threads are
 * independent.  Each call that draws makes the player's context current
 * first, so several players may share a thread. */
#ifndef GLSCENE_H
#define GLSCENE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLSCENE_VERSION "0.1.0"

/* The reason a call failed: one line, possibly followed by a source line
 * and a caret line (camera files, scene sources), NUL-terminated. */
typedef struct {
    char message[1024];
} glscene_error;

/* The GL backend (spec/backends.md): AUTO: EGL where it gives a context,
 * OSMesa otherwise. */
typedef enum {
    GLSCENE_BACKEND_AUTO = 0,
    GLSCENE_BACKEND_EGL = 1,
    GLSCENE_BACKEND_OSMESA = 2
} glscene_backend;

/* Anti-aliasing sample pattern (spec/antialiasing.md); LATTICE is the
 * default, as in glsplay. */
typedef enum { GLSCENE_AA_LATTICE = 0, GLSCENE_AA_GRID = 1, GLSCENE_AA_STRATIFIED = 2 } glscene_aa_pattern;

/* glscene_options' aa for exact coverage (glsplay --aa exact,
 * spec/antialiasing.md "Exact coverage"): each pixel of the image the
 * exact area of what is visible in it times its colour, no samples
 * (textures, lighting and the alpha test are sampled at 64 points in the
 * pixels they vary in; glscene_open refuses a scene with shadows).
 * Depth, instance and normals stay the pixel centre's. */
#define GLSCENE_AA_EXACT UINT32_MAX

/* Options of glscene_open.  All zero (or NULL) is the default: automatic
 * backend, glsplay's default anti-aliasing (--aa auto: exact coverage,
 * or one sample a pixel for a scene with shadows), lattice pattern,
 * black background. */
typedef struct {
    glscene_backend backend;
    uint32_t aa;                /* 0: the default (--aa auto); N: N x N samples a pixel
                                   (glsplay --aa N), 1 one; GLSCENE_AA_EXACT: exact
                                   coverage (--aa exact)                                 */
    glscene_aa_pattern pattern; /* glsplay --pattern                                     */
    uint64_t seed;              /* stratified jitter seed (--seed)                      */
    float background[3];        /* colour where no surface is, 0..1 (--background)      */
} glscene_options;

/* An OpenCV pinhole camera (spec/camera.md): Pc = R P + T, R row-major
 * world to camera; the image is width x height pixels, pixel (u, v) is
 * column u, row v, top row first. */
typedef struct {
    uint32_t width, height;
    double fx, fy, cx, cy, skew;
    double R[9];
    double T[3];
    double near, far;
} glscene_camera;

/* Where glscene_render writes, caller-owned, row-major, top row first,
 * width x height pixels of the camera; any may be NULL (not rendered).
 *   rgb8:     3 bytes a pixel, the image as glsplay's PNG has it
 *   rgbf:     3 floats a pixel, 0..1, the image as glsplay's PFM has it
 *   depth:    Zc (distance along the optical axis), +inf where no surface
 *   instance: the instance id as glsplay's instance output numbers it
 *             (1 + rank among the instances that draw, call-path order;
 *             0: background); glscene_instance_path names it
 *   normals:  3 floats a pixel, unit camera-frame normal (x right, y down,
 *             z forward), 0 0 0 where no surface
 * The image is anti-aliased as the options say; depth, instance and
 * normals come from the pixel centre (never blended), as glsplay's. */
typedef struct {
    uint8_t *rgb8;
    float *rgbf;
    float *depth;
    uint32_t *instance;
    float *normals;
} glscene_buffers;

typedef struct glscene_player glscene_player;

/* The library's version, GLSCENE_VERSION of the build. */
const char *glscene_version(void);

/* Load and check a bundle, build its scene, create the GL context and the
 * renderer.  opt NULL: the defaults.  NULL with e->message on failure. */
glscene_player *glscene_open(const char *bundle_path, const glscene_options *opt, glscene_error *e);

/* Free everything the player holds, its GL context included.  NULL: nothing. */
void glscene_close(glscene_player *p);

/* Read a camera file (.cam, or OpenCV YAML), the pose in the world, as
 * glsplay --camera without a trajectory.  0, or -1 with e. */
int glscene_camera_from_file(const char *path, glscene_camera *out, glscene_error *e);

/* Fill *out from numbers, checked as a camera file's values are: width
 * and height whole in 1..16384, fx, fy > 0, 0 < near < far within the
 * float depth range, R a rotation (re-orthonormalised within 1e-4, as a
 * file's).  R NULL: identity; T NULL: zero.  0, or -1 with e. */
int glscene_camera_set(glscene_camera *out, uint32_t width, uint32_t height, double fx, double fy, double cx,
                       double cy, double skew, const double R[9], const double T[3], double near, double far,
                       glscene_error *e);

/* Move the instance the scene names `name` (a named call, as glsplay
 * --motion NAME=FILE): R, T object-to-parent (R row-major; NULL R: back
 * to the identity, T ignored).  Holds for every later render.  0, or -1
 * with e (no such instance, R not a rotation). */
int glscene_move_instance(glscene_player *p, const char *name, const double R[9], const double T[3],
                          glscene_error *e);

/* Render one frame through camera c into out.  0, or -1 with e (the
 * camera's size beyond what GL allows, out of memory). */
int glscene_render(glscene_player *p, const glscene_camera *c, const glscene_buffers *out, glscene_error *e);

/* The call path of instance id (glscene_buffers.instance), e.g.
 * "Demo > Car#2"; NULL for 0 or an id the scene does not have.  The
 * string lives as long as the player. */
const char *glscene_instance_path(glscene_player *p, uint32_t id);
/* The number of instance ids (the largest id). */
uint32_t glscene_instance_count(glscene_player *p);

/* What glsc does: compile the scene file (or dotted top-level name)
 * scene_path, searching the nroots roots (directories or library
 * bundles, in order; none: the current directory), into out_bundle
 * (written whole or not at all).  0, or -1 with e (the compiler's
 * messages, the first of them whole when they do not all fit). */
int glscene_compile(const char *scene_path, const char *const *roots, size_t nroots, const char *out_bundle,
                    glscene_error *e);

/* The player's full options: what glsplay does, as library calls (a run
 * renders and writes files, sequences, effects, progress: everything
 * glsplay's options ask for; docs/api.md "The player's full options").
 * glsplay itself is these calls.  A run is built from glsplay's
 * command-line arguments (glsplay --help, spec/outputs.md), then run. */
typedef struct glscene_play glscene_play;

/* A run with glsplay's defaults (progress off); NULL: out of memory. */
glscene_play *glscene_play_new(void);
/* Free it; NULL: nothing. */
void glscene_play_free(glscene_play *r);

/* Take glsplay's argument arg, with next the one after it (NULL: none);
 * the bundle is the argument that is not an option.  Strings are copied.
 * Returns how many arguments it took (1 or 2), or -1 when they are a
 * usage mistake (glsplay prints the message with "(try glsplay --help)"
 * and exits 2), or -2 when this build cannot do what they ask (a GL
 * backend it was built without) or memory ran out; the message is in e
 * (at most 1023 bytes) and whole in glscene_play_message.  --help is
 * glsplay's, not the library's. */
int glscene_play_arg(glscene_play *r, const char *arg, const char *next, glscene_error *e);

/* The checks between arguments, once they are all given (a bundle, a
 * camera, an output directory or --explain, ...).  0, or -1 with e. */
int glscene_play_check(glscene_play *r, glscene_error *e);

/* Render and write what the arguments ask for.  Messages go to errs as
 * glsplay prints them ("glsplay: error: ...", notes, progress), --explain's
 * plan to out; the library writes to no other stream.  Returns glsplay's
 * exit status: 0 done, 1 an input error, 2 when glscene_play_check fails
 * (it is run first if it was not). */
int glscene_play_run(glscene_play *r, FILE *out, FILE *errs);

/* The whole message of r's last failing call ("" if none). */
const char *glscene_play_message(const glscene_play *r);

/* A camera from its file's text (.cam keys or OpenCV YAML, spec/camera.md)
 * instead of a path, as --camera takes a file: name names it (its output
 * directory for glscene_play_run, its place in a result; a path's name
 * is the file's without the directory and extension).  Messages locate
 * the text's errors as "NAME:line:col".  0, or -1 with e. */
int glscene_play_camera_text(glscene_play *r, const char *name, const char *text, glscene_error *e);

/* One frame of the run into a result the library owns, instead of files:
 * every file the run's arguments would write for frame `frame` (of the
 * trajectory, or --frame's number without one), for each camera, as an
 * array with the values the file holds (docs/api.md "Every output as
 * arrays").  The same plan, passes and arrays as glscene_play_run's;
 * nothing is written or printed, and what only a run writing files does
 * (-o, --explain, --resume, --shard, --write-calib, --progress, --frames)
 * has no effect.  NULL with e (every
 * message of the run, without "glsplay: error: ") on failure.
 * The run stays open in r between calls: the first begins it (reads the
 * bundle, camera files, trajectory and motions, makes a GL context,
 * uploads the scene) and the next render in it; glscene_play_arg or
 * glscene_play_camera_text after a render, a failed render, or
 * glscene_play_free closes it.  Its GL context belongs to the thread of
 * the first call: render and free r there. */
typedef struct glscene_result glscene_result;
glscene_result *glscene_play_render(glscene_play *r, uint64_t frame, glscene_error *e);

/* The frame numbers of the run's --trajectory, in its order, into
 * frames[0..cap) (cap 0: only counted); returns how many it has, or -1
 * with e (no trajectory, a file that cannot be read, a bad row). */
long long glscene_play_trajectory_frames(glscene_play *r, uint64_t *frames, size_t cap, glscene_error *e);

/* An array's samples: unsigned 8, 16 bits, float32 (host order), or the
 * text of a CSV, TXT or JSON file (NUL-terminated beyond its bytes), or a
 * file's bytes (the points' PLY). */
typedef enum {
    GLSCENE_U8 = 1,
    GLSCENE_U16 = 2,
    GLSCENE_F32 = 3,
    GLSCENE_TEXT = 4,
    GLSCENE_BYTES = 5
} glscene_dtype;

/* One output of one camera: dims[0] rows (top first) x dims[1] columns
 * x dims[2] channels (ndim 3; ndim 2: one channel), row-major; text and
 * bytes: ndim 1, dims[0] = bytes.  data lives as long as the result. */
typedef struct {
    glscene_dtype dtype;
    uint32_t ndim;
    size_t dims[3];
    const void *data;
    size_t bytes;
} glscene_array;

/* The cameras of a result, in the run's order, and the name of each. */
size_t glscene_result_cameras(const glscene_result *res);
const char *glscene_result_camera(const glscene_result *res, size_t cam);
/* The names of camera cam's arrays, k < glscene_result_count (NULL
 * beyond): the output words, with the files' own names where a word
 * writes several (flow: "flow" u v float32, "flow_kitti" the PNG's
 * codes, "flowmask"; boxes: "boxes" the KITTI text, "boxes_json";
 * instance and class: "instances" the JSON table). */
size_t glscene_result_count(const glscene_result *res, size_t cam);
const char *glscene_result_name(const glscene_result *res, size_t cam, size_t k);
/* Camera cam's array `name` into *out.  0, or -1 with e when there is
 * no such camera or array (the message lists the result's). */
int glscene_result_array(const glscene_result *res, size_t cam, const char *name, glscene_array *out,
                         glscene_error *e);
/* Free a result and its arrays; NULL: nothing. */
void glscene_result_free(glscene_result *res);

#ifdef __cplusplus
}
#endif
#endif
