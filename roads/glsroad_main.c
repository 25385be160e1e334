/* glsroad: road description -> scene, trajectory and ground truth
 * (spec/road.md).
 *
 *   glsroad ROAD.road -o DIR
 *   glsroad --camera-at FRAME TRAJECTORY CAMERA   (camera file on stdout)
 *   glsroad --list-keys                           (the keys, as spec tables)
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "atomic_write.h"
#include "road.h"
#include "road_outdir.h"
#include "camera.h"
#include "mkdirs.h"
#include "stdout_check.h"
#include "textfile.h"
#include "trajectory.h"
#include "usage.h"

#define USAGE                                                                          \
    "usage: glsroad ROAD.road -o DIR\n"                                                \
    "       glsroad --camera-at FRAME TRAJECTORY CAMERA\n"                             \
    "       glsroad --list-keys\n"                                                     \
    "       glsroad --help | --version\n"                                              \
    "The first form writes DIR/road.scene, DIR/roadobj/*.scene, DIR/trajectory.txt,\n" \
    "DIR/poses_kitti.txt, DIR/poses_tum.txt, DIR/lanes.txt, DIR/vehicles.txt and\n"    \
    "DIR/motion/NAME.txt per vehicle, replacing a previous output in DIR as a whole.\n" \
    "The second prints CAMERA (a camera file relative to the rig) with R and T\n"      \
    "replaced by that camera's pose in the world at FRAME of TRAJECTORY.\n"            \
    "The third prints the keys of a road description, as spec/road.md's tables.\n"     \
    "See spec/road.md.\n"

/* a usage error: the message, then the usage text */
#define usage_error(...) gls_usage_error("glsroad", "\n" USAGE, __VA_ARGS__)

static int make_road(const char *in, const char *dir)
{
    char err[1024];
    size_t len;
    char *text = gls_text_read(in, ROAD_MAX_FILE, "road description", &len, err, sizeof err);
    if (!text) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    road_desc d;
    road_geo g;
    int rc = 1;
    /* the description stays in memory: errors found after parsing quote it */
    if (road_parse(text, len, in, &d, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        free(text);
        return 1;
    }
    if (road_geo_init(&g, &d, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        road_desc_free(&d);
        free(text);
        return 1;
    }
    road_buf scene = {0}, tree = {0}, car = {0}, lanes = {0}, traj = {0}, kitti = {0}, tum = {0}, veh = {0};
    static const char *const fixed[] = {"road.scene",      "roadobj/Tree.scene", "roadobj/Car.scene",
                                        "lanes.txt",       "trajectory.txt",     "poses_kitti.txt",
                                        "poses_tum.txt",   "vehicles.txt"};
    const road_buf *bufs[] = {&scene, &tree, &car, &lanes, &traj, &kitti, &tum, &veh};
    enum { NFIXED = sizeof fixed / sizeof fixed[0] };
    /* then motion/NAME.txt per vehicle */
    int nfiles = NFIXED + d.nveh;
    road_out_file *files = calloc((size_t)nfiles, sizeof *files);
    road_buf *motion = calloc((size_t)d.nveh + 1, sizeof *motion);
    char (*mnames)[ROAD_VEHICLE_NAME_MAX + 16] = calloc((size_t)d.nveh + 1, sizeof *mnames);
    if (!files || !motion || !mnames) {
        fprintf(stderr, "glsroad: error: out of memory\n");
        goto out;
    }
    for (int i = 0; i < nfiles; i++) {
        if (i >= NFIXED)
            snprintf(mnames[i - NFIXED], sizeof mnames[0], "motion/%s.txt", d.veh[i - NFIXED].name);
        files[i].name = i < NFIXED ? fixed[i] : mnames[i - NFIXED];
    }
    /* cheap checks first (limits, an output directory that may not be
       replaced), then everything is computed, then written as a whole:
       an error leaves DIR as it was */
    if (road_check_limits(&g, err, sizeof err) || road_outdir_check(dir, files, nfiles, err, sizeof err) ||
        road_emit_scene(&g, &scene, &tree, &car, err, sizeof err) || road_emit_lanes(&g, &lanes, err, sizeof err) ||
        road_emit_motion(&g, &traj, &kitti, &tum, &veh, motion, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        goto out;
    }
    for (int i = 0; i < nfiles; i++) {
        const road_buf *rb = i < NFIXED ? bufs[i] : &motion[i - NFIXED];
        files[i].data = rb->text;
        files[i].len = rb->len;
    }
    if (road_outdir_write(dir, files, nfiles, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        goto out;
    }
    long frames = 0;
    for (size_t i = 0; i < traj.len; i++)
        frames += traj.text[i] == '\n' && i + 1 < traj.len && traj.text[i + 1] != '#';
    printf("glsroad: %s: road %.3f m, %ld frames at %g fps -> %s\n", in, g.c.length, frames, d.fps, dir);
    rc = 0;
out:
    free(scene.text);
    free(tree.text);
    free(car.text);
    free(lanes.text);
    free(traj.text);
    free(kitti.text);
    free(tum.text);
    free(veh.text);
    for (int i = 0; motion && i < d.nveh; i++)
        free(motion[i].text);
    free(motion);
    free(mnames);
    free(files);
    road_geo_free(&g);
    road_desc_free(&d);
    free(text);
    return rc;
}

static int camera_at(const char *frame_s, const char *traj_path, const char *cam_path)
{
    char err[1024];
    uint64_t first, end;
    if (gls_traj_range(frame_s, &first, &end, err, sizeof err) || end != first + 1)
        return usage_error("--camera-at: '%s' is not a frame number", frame_s);
    size_t len;
    char *text = gls_text_read(cam_path, GLS_CAMERA_MAX_FILE, "camera file", &len, err, sizeof err);
    if (!text) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    /* the camera relative to the rig: parsed and checked by the player's
       own camera-file parser, so both tools accept the same files */
    gls_camera cam;
    if (gls_camera_parse(text, len, cam_path, GLS_POSE_RIG, stderr, &cam, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        free(text);
        return 1;
    }
    const double *Rc = cam.R, *Tc = cam.T;
    gls_traj *t = gls_traj_open(traj_path, stderr, err, sizeof err);
    if (!t) {
        fprintf(stderr, "%s\n", err);
        free(text);
        return 1;
    }
    gls_traj_pose pose;
    int r;
    while ((r = gls_traj_next(t, &pose, err, sizeof err)) == 1 && pose.frame < first) {
    }
    gls_traj_close(t);
    if (r < 0 || r == 0 || pose.frame != first) {
        if (r >= 0)
            fprintf(stderr, "%s: error: no frame %llu in the trajectory\n", traj_path, (unsigned long long)first);
        else
            fprintf(stderr, "%s\n", err);
        free(text);
        return 1;
    }
    double R[9], T[3];
    gls_traj_compose(Rc, Tc, pose.R, pose.T, R, T);
    /* the camera file again, with R and T replaced and its pose declared a
       world pose (a 'pose rig' line becomes 'pose world') */
    printf("# %s at frame %llu (t = %.17g s) of %s\n", cam_path, (unsigned long long)first, pose.time, traj_path);
    if (!cam.pose)
        printf("pose world\n");
    for (char *p = text; *p;) {
        char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        size_t skip = strspn(p, " \t\r");
        int key = skip < n && (p[skip] == 'R' || p[skip] == 'T') &&
                  (skip + 1 == n || strchr(" \t\r#", p[skip + 1]));
        int pose_key = n - skip >= 4 && !strncmp(p + skip, "pose", 4) && (skip + 4 == n || strchr(" \t\r#", p[skip + 4]));
        if (pose_key) {
            printf("pose world\n");
        } else if (key) {
            double *v = p[skip] == 'R' ? R : T;
            int m = p[skip] == 'R' ? 9 : 3;
            printf("%c ", p[skip]);
            road_nums(stdout, v, m, " ");
            printf("\n");
        } else {
            fwrite(p, 1, n, stdout);
            printf("\n");
        }
        p += n + (nl ? 1 : 0);
    }
    free(text);
    return 0; /* main's exit check reports a failed write */
}

int main(int argc, char **argv)
{
    gls_check_stdout_at_exit("glsroad");
    const char *in = NULL, *out = NULL;
    if (argc >= 2 && !strcmp(argv[1], "--camera-at")) {
        if (argc != 5)
            return usage_error("%s takes FRAME TRAJECTORY CAMERA", "--camera-at");
        if (!argv[3][0] || !argv[4][0]) /* names no file (spec/exit_status.md) */
            return usage_error("--camera-at: an empty %s name", !argv[3][0] ? "trajectory" : "camera file");
        return camera_at(argv[2], argv[3], argv[4]);
    }
    if (argc == 2 && !strcmp(argv[1], "--list-keys")) {
        road_list_keys(stdout);
        return 0; /* main's exit check reports a failed write */
    }
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            gls_stdout_text(USAGE);
            return 0;
        } else if (!strcmp(argv[i], "--version")) {
            return gls_version("glsroad");
        } else if (!strcmp(argv[i], "-o")) {
            if (i + 1 >= argc)
                return usage_error("%s needs a directory", "-o");
            out = argv[++i];
            if (!out[0]) /* names no directory (spec/exit_status.md) */
                return usage_error("%s needs a non-empty directory", "-o");
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return usage_error("unknown option '%s'", argv[i]);
        } else if (in) {
            return usage_error("more than one road description ('%s')", argv[i]);
        } else if (!argv[i][0]) {
            return usage_error("%s", "an empty road description name");
        } else {
            in = argv[i];
        }
    }
    if (!in)
        return usage_error("%s", "no road description given");
    if (!out)
        return usage_error("%s", "no output directory: give -o DIR");
    return make_road(in, out);
}
