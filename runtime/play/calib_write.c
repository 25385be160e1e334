/* glsplay --write-calib (calib_write.h; conventions in spec/outputs.md
 * "Calibration files"). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "atomic_write.h"
#include "calib_write.h"
#include "frames.h"
#include "numfmt.h"
#include "buf.h"
#include "trajectory.h"
#include "vec.h"

#define MAXPATH 4096

#define putf gls_buf_printf

/* Number styles: the shortest text that reads back as the same double
 * (gls_fmt_double) everywhere; in YAML with a '.' in the mantissa, so that
 * OpenCV reads a real (a bare "12345678901" would be its 32-bit int) and
 * PyYAML a float ("1e-05" is a string to YAML 1.1, "1.0e-05" a float). */
typedef enum { NUM_PLAIN, NUM_YAML } numstyle;

static int num(gls_buf *b, double v, numstyle st)
{
    char s[48];
    gls_fmt_double(s, sizeof s, v);
    if (st == NUM_YAML && !strchr(s, '.')) {
        char *e = strchr(s, 'e');
        char tail[48] = "";
        if (e) {
            snprintf(tail, sizeof tail, "%s", e);
            *e = 0;
        }
        return putf(b, "%s.0%s", s, tail);
    }
    return putf(b, "%s", s);
}

/* n numbers separated by sep */
static int nums(gls_buf *b, const double *v, size_t n, const char *sep, numstyle st)
{
    for (size_t i = 0; i < n; i++)
        if ((i && putf(b, "%s", sep)) || num(b, v[i], st))
            return -1;
    return 0;
}

static void camera_k(const gls_camera *c, double K[9])
{
    const double k[9] = {c->fx, c->skew, c->cx, 0, c->fy, c->cy, 0, 0, 1};
    memcpy(K, k, sizeof k);
}

static const double zero5[5] = {0, 0, 0, 0, 0};

/* The lens as the calibration files hold it (spec/outputs.md): the
 * coefficients in OpenCV's order, at least 5 for plumb_bob (k3 = 0 when
 * the camera gave 4), and ROS's model name; a pinhole camera's 5 zeros. */
static const char *lens_coeffs(const gls_camera *c, double d[8], int *n)
{
    const gls_distortion *ds = &c->dist;
    memcpy(d, zero5, sizeof zero5);
    *n = 5;
    if (ds->model == GLS_LENS_NONE)
        return "plumb_bob";
    memcpy(d, ds->k, ds->n * sizeof *d);
    if (ds->model == GLS_LENS_FISHEYE) {
        *n = 4;
        return "equidistant";
    }
    *n = ds->n == 8 ? 8 : 5;
    return ds->n == 8 ? "rational_polynomial" : "plumb_bob";
}
static const double ident[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

void gls_calib_relative(const gls_camera *c0, const gls_camera *ci, double R[9], double t[3])
{
    double R0t[9];
    if (memcmp(c0->R, ci->R, sizeof ci->R) == 0) {
        memcpy(R, ident, sizeof ident);
    } else {
        rm_transpose(c0->R, R0t);
        rm_mul(ci->R, R0t, R);
    }
    rv3 r = rm_apply(R, rv(c0->T[0], c0->T[1], c0->T[2]));
    if (memcmp(R, ident, sizeof ident) == 0)
        r = rv(c0->T[0], c0->T[1], c0->T[2]);
    t[0] = ci->T[0] - r.x;
    t[1] = ci->T[1] - r.y;
    t[2] = ci->T[2] - r.z;
}

/* K [R | t], 3x4 row-major */
static void projection(const gls_camera *c, const double R[9], const double t[3], double P[12])
{
    double K[9];
    camera_k(c, K);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++)
                s += K[3 * i + k] * (j < 3 ? R[3 * k + j] : t[k]);
            P[4 * i + j] = s;
        }
}

/* One !!opencv-matrix, laid out as cv::FileStorage writes it. */
static int cv_matrix(gls_buf *b, const char *key, const double *v, int rows, int cols)
{
    return putf(b, "%s: !!opencv-matrix\n   rows: %d\n   cols: %d\n   dt: d\n   data: [ ", key, rows, cols) ||
           nums(b, v, (size_t)rows * cols, ", ", NUM_YAML) || putf(b, " ]\n");
}

/* The camera's effects (spec/camera.md "OpenCV camera files"), under the
 * .cam file's key names, only those it has: nothing for a camera without.
 * Words and vignetting's "poly a1 a2 a3" are strings, as cv::FileStorage
 * writes them; noise_seed too, quoted: OpenCV reads a bare number above
 * 2^31 - 1 wrongly, and a seed is a 64-bit whole number. */
static int opencv_effects(gls_buf *b, const gls_camera *c)
{
    const gls_sensor *se = &c->sensor;
    int e = 0;
    if (se->vignetting == GLS_VIGNETTING_COS4)
        e = e || putf(b, "vignetting: cos4\n");
    if (se->vignetting == GLS_VIGNETTING_POLY)
        e = e || putf(b, "vignetting: \"poly ") || nums(b, se->poly, 3, " ", NUM_PLAIN) || putf(b, "\"\n");
    if (se->on & GLS_SENSOR_GAIN)
        e = e || putf(b, "gain: ") || num(b, se->gain, NUM_YAML) || putf(b, "\n");
    if (se->on & GLS_SENSOR_SHOT)
        e = e || putf(b, "shot_noise: ") || num(b, se->shot_k, NUM_YAML) || putf(b, "\n");
    if (se->on & GLS_SENSOR_READ)
        e = e || putf(b, "read_noise: ") || num(b, se->read_sigma, NUM_YAML) || putf(b, "\n");
    if (se->on & GLS_SENSOR_NOISE)
        e = e || putf(b, "noise_seed: \"%llu\"\n", (unsigned long long)se->seed);
    if (se->on & GLS_SENSOR_BAYER)
        e = e || putf(b, "bayer: %s\n", se->bayer);
    const struct {
        const char *key;
        double v;
    } fx[] = {{"shutter", c->shutter}, {"line_delay", c->line_delay}, {"aperture", c->aperture}, {"focus", c->focus}};
    for (size_t i = 0; i < sizeof fx / sizeof fx[0]; i++)
        if (fx[i].v > 0)
            e = e || putf(b, "%s: ", fx[i].key) || num(b, fx[i].v, NUM_YAML) || putf(b, "\n");
    if (c->exposure_samples)
        e = e || putf(b, "exposure_samples: %u\n", c->exposure_samples);
    return e ? -1 : 0;
}

int gls_calib_opencv_yaml(gls_buf *b, const gls_camera *c, const char *name, uint32_t frame)
{
    double K[9], D[8];
    int nd;
    camera_k(c, K);
    lens_coeffs(c, D, &nd);
    return putf(b, "%%YAML:1.0\n---\ncamera_name: ") || gls_buf_quoted(b, name, 0) ||
           putf(b, "\nframe: %u\nimage_width: %u\nimage_height: %u\n", frame, c->width, c->height) ||
           cv_matrix(b, "camera_matrix", K, 3, 3) || cv_matrix(b, "distortion_coefficients", D, 1, nd) ||
           (c->dist.model == GLS_LENS_FISHEYE && putf(b, "distortion_model: fisheye\n")) ||
           cv_matrix(b, "R", c->R, 3, 3) || cv_matrix(b, "T", c->T, 3, 1) || putf(b, "near: ") ||
           num(b, c->near, NUM_YAML) || putf(b, "\nfar: ") || num(b, c->far, NUM_YAML) ||
           putf(b, "\npose: world\n") || opencv_effects(b, c);
}

int gls_calib_kitti(gls_buf *b, const gls_camera *cams, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        double R[9], t[3], P[12];
        gls_calib_relative(&cams[0], &cams[i], R, t);
        projection(&cams[i], R, t, P);
        if (putf(b, "P%zu: ", i) || nums(b, P, 12, " ", NUM_PLAIN) || putf(b, "\n"))
            return -1;
    }
    return 0;
}

/* Rectified with camera 0 (ROS's stereo convention applies): the same
 * orientation within 1e-9 per entry of R_i0, the offset along x only
 * (y and z within 1e-9 of |t|), and rows aligned (the same fy and cy). */
#define RECTIFIED_TOL 1e-9
static int rectified(const gls_camera *c0, const gls_camera *ci, const double R[9], const double t[3])
{
    for (int k = 0; k < 9; k++)
        if (fabs(R[k] - ident[k]) > RECTIFIED_TOL)
            return 0;
    double tl = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    return fabs(t[1]) <= RECTIFIED_TOL * tl && fabs(t[2]) <= RECTIFIED_TOL * tl && ci->fy == c0->fy &&
           ci->cy == c0->cy;
}

static int ros_matrix(gls_buf *b, const char *key, const double *v, int rows, int cols)
{
    return putf(b, "%s:\n  rows: %d\n  cols: %d\n  data: [", key, rows, cols) ||
           nums(b, v, (size_t)rows * cols, ", ", NUM_YAML) || putf(b, "]\n");
}

int gls_calib_ros_yaml(gls_buf *b, const gls_camera *cams, const char *const *names, size_t i)
{
    const gls_camera *c = &cams[i];
    double R[9], t[3], K[9], P[12];
    gls_calib_relative(&cams[0], c, R, t);
    camera_k(c, K);
    int rect = i == 0 || rectified(&cams[0], c, R, t);
    /* P = [K | (Tx, 0, 0)]: Tx = fx t_x = -fx B, B the baseline of camera i
       to the right of camera 0; 0 for camera 0 and for a camera written as
       monocular */
    const double p[12] = {K[0], K[1], K[2], rect ? c->fx * t[0] : 0, 0, K[4], K[5], 0, 0, 0, 1, 0};
    memcpy(P, p, sizeof p);
    if (!rect && (putf(b, "# not rectified with camera 0 (") || putf(b, "%s", names[0]) ||
                  putf(b, "): written as a monocular camera, P = [K | 0] (spec/outputs.md)\n")))
        return -1;
    double D[8];
    int nd;
    const char *model = lens_coeffs(c, D, &nd);
    return putf(b, "image_width: %u\nimage_height: %u\ncamera_name: ", c->width, c->height) ||
           gls_buf_quoted(b, names[i], 0) || putf(b, "\n") || ros_matrix(b, "camera_matrix", K, 3, 3) ||
           putf(b, "distortion_model: %s\n", model) || ros_matrix(b, "distortion_coefficients", D, 1, nd) ||
           ros_matrix(b, "rectification_matrix", ident, 3, 3) || ros_matrix(b, "projection_matrix", P, 3, 4);
}

/* rows x cols as a JSON array of rows */
static int json_matrix(gls_buf *b, const char *key, const double *v, int rows, int cols)
{
    if (putf(b, "\"%s\": [", key))
        return -1;
    for (int r = 0; r < rows; r++)
        if (putf(b, "%s[", r ? ", " : "") || nums(b, v + r * cols, (size_t)cols, ", ", NUM_PLAIN) || putf(b, "]"))
            return -1;
    return putf(b, "]");
}

/* The JSON of one frame: every camera with its world pose (world[i]) and,
 * with a trajectory, its pose relative to the rig (rig[i]; else NULL). */
static int calib_json(gls_buf *b, uint32_t frame, const double *time, const gls_camera *world,
                      const gls_camera *rig, const char *const *names, size_t n)
{
    if (putf(b, "{\n  \"frame\": %u,\n", frame) ||
        (time && (putf(b, "  \"time\": ") || num(b, *time, NUM_PLAIN) || putf(b, ",\n"))) ||
        putf(b, "  \"model\": \"opencv-pinhole\",\n  \"cameras\": [\n"))
        return -1;
    for (size_t i = 0; i < n; i++) {
        const gls_camera *c = &world[i];
        double K[9], R[9], t[3], P[12], D[8];
        int nd;
        const char *model = lens_coeffs(c, D, &nd);
        camera_k(c, K);
        gls_calib_relative(&world[0], c, R, t);
        if (rig)
            gls_calib_relative(&rig[0], &rig[i], R, t);
        projection(c, R, t, P);
        if (putf(b, "    {\"name\": ") || gls_buf_quoted(b, names[i], 1) ||
            putf(b, ", \"image_width\": %u, \"image_height\": %u,\n     ", c->width, c->height) ||
            json_matrix(b, "K", K, 3, 3) || putf(b, ", \"dist\": [") || nums(b, D, (size_t)nd, ", ", NUM_PLAIN) ||
            putf(b, "]") || (c->dist.model && putf(b, ", \"distortion_model\": \"%s\"", model)) ||
            putf(b, ",\n     \"pose_frame\": \"world\", ") || json_matrix(b, "R", c->R, 3, 3) ||
            putf(b, ", \"T\": [") || nums(b, c->T, 3, ", ", NUM_PLAIN) || putf(b, "],\n     \"near\": ") ||
            num(b, c->near, NUM_PLAIN) || putf(b, ", \"far\": ") || num(b, c->far, NUM_PLAIN) ||
            putf(b, ",\n     ") || json_matrix(b, "P_kitti", P, 3, 4))
            return -1;
        if (rig && (putf(b, ",\n     \"rig\": {") || json_matrix(b, "R", rig[i].R, 3, 3) || putf(b, ", \"T\": [") ||
                    nums(b, rig[i].T, 3, ", ", NUM_PLAIN) || putf(b, "]}")))
            return -1;
        if (putf(b, "}%s\n", i + 1 < n ? "," : ""))
            return -1;
    }
    return putf(b, "  ]\n}\n");
}

/* Write b to OUTDIR/[NAME/]FILE; 0, or 1 after a message. */
static int write_out(FILE *errs, const char *outdir, const char *name, const char *file, gls_buf *b, int built)
{
    char path[MAXPATH];
    int k = name ? snprintf(path, sizeof path, "%s/%s/%s", outdir, name, file)
                 : snprintf(path, sizeof path, "%s/%s", outdir, file);
    if (k < 0 || (size_t)k >= sizeof path) {
        fprintf(errs, "glsplay: error: calibration output path for %s is too long\n", file);
        return 1;
    }
    if (built) {
        fprintf(errs, "glsplay: error: out of memory writing %s\n", path);
        return 1;
    }
    if (gls_write_file_atomic(path, b->data, b->len)) {
        fprintf(errs, "glsplay: error: cannot write %s: %s\n", path, gls_write_error(path, errno));
        return 1;
    }
    return 0;
}

/* The files of one frame: NAME/calib_F.yml per camera, calib_F.json. */
static int write_frame(const gls_play_opts *o, const gls_camera *world, const gls_camera *rig,
                       const char *const *names, uint32_t frame, const double *time, gls_buf *b, FILE *errs)
{
    char file[64];
    for (size_t i = 0; i < o->ncameras; i++) {
        b->len = 0;
        snprintf(file, sizeof file, "calib_%06u.yml", frame);
        if (write_out(errs, o->outdir, names[i], file, b, gls_calib_opencv_yaml(b, &world[i], names[i], frame)))
            return 1;
    }
    b->len = 0;
    snprintf(file, sizeof file, "calib_%06u.json", frame);
    return write_out(errs, o->outdir, NULL, file, b, calib_json(b, frame, time, world, rig, names, o->ncameras));
}

int gls_calib_write(const gls_play_opts *o, const gls_traj_text *traj, const gls_camera *cams,
                    const char *const *names, FILE *errs)
{
    gls_buf b = {0};
    int rc = 1;
    gls_camera *world = NULL;
    gls_frames f;
    memset(&f, 0, sizeof f); /* closed at out: even when never opened */
    /* the rig's files: relative poses, the same in every frame; KITTI's
       calib.txt is for rectified images and holds no lens */
    for (size_t i = 0; i < o->ncameras; i++)
        if (cams[i].dist.model)
            fprintf(errs, "glsplay: note: camera %s has lens distortion: calib.txt (KITTI, rectified images) holds "
                          "only its pinhole part P = K [R | t]; the coefficients are in %s/calib_F.yml, "
                          "%s/camera_info.yaml and calib_F.json\n", names[i], names[i], names[i]);
    if (write_out(errs, o->outdir, NULL, "calib.txt", &b, gls_calib_kitti(&b, cams, o->ncameras)))
        goto out;
    for (size_t i = 0; i < o->ncameras; i++) {
        b.len = 0;
        if (write_out(errs, o->outdir, names[i], "camera_info.yaml", &b,
                      gls_calib_ros_yaml(&b, cams, names, i)))
            goto out;
    }
    /* the files of each frame follow --shard (shard.h); the rig's, above,
       are the same bytes from every shard */
    if (!traj) {
        rc = gls_shard_has(&o->shard, o->frame, o->frame) ? write_frame(o, cams, NULL, names, o->frame, NULL, &b, errs)
                                                          : 0;
        goto out;
    }
    /* every frame of the range, read as the renderer read them (the
       trajectory was checked before the first was rendered) */
    char err[1024];
    world = malloc(o->ncameras * sizeof *world);
    if (!world || gls_frames_open(&f, traj, NULL, o->frame_first, o->frame_end, &o->shard)) {
        fprintf(errs, "glsplay: error: out of memory\n");
        goto out;
    }
    gls_traj_pose p;
    gls_frame_mark m;
    int got;
    while ((got = gls_frames_next(&f, &p, &m, err, sizeof err)) == 1) {
        if (p.frame > UINT32_MAX)
            break;
        if (!m.mine)
            continue;
        for (size_t i = 0; i < o->ncameras; i++) {
            world[i] = cams[i];
            gls_traj_compose(cams[i].R, cams[i].T, p.R, p.T, world[i].R, world[i].T);
            world[i].pose = GLS_POSE_WORLD;
        }
        if (write_frame(o, world, cams, names, (uint32_t)p.frame, &p.time, &b, errs))
            goto out;
    }
    if (got < 0) {
        fprintf(errs, "%s\n", err);
        goto out;
    }
    rc = 0;
out:
    gls_frames_close(&f);
    free(world);
    free(b.data);
    return rc;
}
