/* The files of one camera frame as a writer job (frame_writer.h): the
 * pixels read back or accumulated, the paths, and the frame record.  Run,
 * it removes the old record, encodes and writes each file atomically
 * (outputs.h, atomic_write.h), then writes the record (frame_record.h),
 * so the record exists only once every file of the frame is complete.
 * With a sink (libglscene's glscene_play_render) it hands the sink each
 * file's array instead, the arrays the encoders make, and writes
 * nothing. */
#ifndef GLS_FRAME_FILES_H
#define GLS_FRAME_FILES_H

#include <stdint.h>
#include "camera.h"
#include "exact.h"
#include "gt_landmarks.h"
#include "frame_writer.h"
#include "gt_table.h"
#include "out_boxes.h"
#include "output_table.h"
#include "progress_json.h"

#define GLS_FRAME_PATH 4096

/* One file of a camera frame as the array its encoder makes (the
 * library's result, glscene_result_array): the pixels top row first,
 * dims[0] rows, dims[1] columns, dims[2] channels (ndim 2: one), in
 * the sample type the file holds (the 16-bit PNGs' codes, ids and flow
 * included); the text of the CSV, TXT and JSON files; the bytes of the
 * PLY.  data is malloc'd and the taker's. */
typedef enum { GLS_ARR_U8 = 1, GLS_ARR_U16 = 2, GLS_ARR_F32 = 3, GLS_ARR_TEXT = 4, GLS_ARR_BYTES = 5 } gls_arr_type;
typedef struct {
    gls_arr_type type;
    uint32_t ndim;       /* 2 or 3; 1 for text and bytes (dims[0] bytes) */
    size_t dims[3];
    void *data;
    size_t bytes;
} gls_frame_array;

/* Where a camera frame's arrays go instead of its files (gls_play_opts'
 * sink, player.h): take is called once a file the frame plan writes, in
 * the table's order, from the thread that runs the writer's jobs; it
 * owns a->data from then on.  0, or -1 with err. */
typedef struct gls_frame_sink gls_frame_sink;
struct gls_frame_sink {
    int (*take)(gls_frame_sink *s, const char *camera, uint32_t frame, unsigned bit, gls_frame_array *a, char *err,
                size_t errlen);
};

typedef struct {
    gls_write_job job; /* first: the writer sees this */
    gls_camera cam;    /* size; the points' back-projection */
    const char *name;  /* camera name, for messages (outlives the job) */
    uint32_t frame;    /* for messages and the JSON files */
    gls_image_format image_format;
    int image_mosaic;  /* the image is one sample a pixel (a Bayer mosaic, sensor.h) */
    gls_float_format float_format; /* depth, disparity, a pfm image */
    double fxB;        /* disparity: fx B of the rectified pair (out_disparity.h) */
    double depth_scale; /* depth16: codes of Zc * depth_scale */
    /* the buffers, owned by the job (freed with it); NULL when unused:
     * rgba (a plain render's image, the points' colours), image (the image
     * in its output format when it is not rgba), z (depth), mask (the
     * edges map); the disparity is made from z by the writer */
    uint8_t *rgba, *mask;
    float *flow;        /* u v a pixel (gt_flow.h)               */
    uint8_t *flowmask;  /* GLS_FLOW_* a pixel                    */
    gls_box *boxes;     /* boxes of the frame (gt_boxes.h)       */
    size_t nboxes;
    const gls_box_names *box_names; /* the run's, outlives the job */
    void *image;
    float *z;
    double (*row_pose)[12]; /* rolling shutter: each row's camera pose for the points, or NULL */
    gls_landmarks *landmarks; /* --outputs landmarks: this frame's, or NULL */
    /* the ground-truth pass (gt_pass.h): instance per pixel, normals;
     * gt, the run's ids (outlives the job) */
    uint32_t *gt_inst;
    float *normal;
    const gls_gt_table *gt;
    gls_exact_cover *cover; /* --outputs coverage (exact.h), or NULL */
    gls_exact_seg *segs;    /* --outputs edge_segments (exact.h), or NULL */
    size_t nsegs;
    uint64_t buffer_bytes; /* for the out-of-memory message */
    size_t nfiles;
    struct {
        unsigned bit; /* GLS_OUT_* */
        char path[GLS_FRAME_PATH];
    } files[GLS_OUT_KINDS]; /* one a kind at most (output_table.h) */
    char record[GLS_FRAME_PATH], record_text[1024];
    /* --progress json: told once the record is written (NULL: not) */
    gls_progress_json *json;
    /* NULL: the files are written; else each file's array goes here and
     * nothing is written (no record, no progress) */
    gls_frame_sink *sink;
} gls_frame_files;

/* A zeroed job with its run and destroy set, or NULL. */
gls_frame_files *gls_frame_files_new(void);

/* File bit of f as the array its encoder makes (above; the disparity
 * disp made by the job).  0, or -1 when out of memory. */
int gls_frame_array_make(const gls_frame_files *f, unsigned bit, const float *disp, gls_frame_array *a);

/* The line said when a camera frame's buffers cannot be had. */
void gls_frame_oom_message(char *buf, size_t len, const char *name, uint32_t w, uint32_t h, uint64_t bytes);

#endif
