/* The trajectory reader and pose composition (runtime/camera/trajectory.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>
#include "check.h"
#include "rotation.h"
#include "textfile.h"
#include "trajectory.h"

static char dir[64];

static const char *write_file(const char *name, const char *text)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

/* Read all frames; returns the count, or -1 with err filled. */
static long read_all(const char *path, gls_traj_pose *last, char *err, size_t errlen)
{
    gls_traj *t = gls_traj_open(path, NULL, err, errlen);
    if (!t)
        return -1;
    long n = 0;
    int r;
    while ((r = gls_traj_next(t, last, err, errlen)) == 1)
        n++;
    gls_traj_close(t);
    return r < 0 ? -1 : n;
}

static void test_read(void)
{
    const char *p = write_file("ok.txt", "# glsroad trajectory 1\n\n"
                                         "0 0 1 0 0 0 1 0 0 0 1 0 0 0\n"
                                         "  5 0.2 0 -1 0  1 0 0  0 0 1  1.5 -2 3e3  # a comment\n"
                                         "7\t0.28\t1 0 0 0 1 0 0 0 1 0.1 0.2 0.30000000000000004\r\n");
    gls_traj *t;
    char err[512];
    CHECK((t = gls_traj_open(p, NULL, err, sizeof err)) != NULL);
    gls_traj_pose q;
    CHECK(gls_traj_next(t, &q, err, sizeof err) == 1);
    CHECK(q.frame == 0 && q.time == 0 && q.R[0] == 1 && q.line == 3);
    CHECK(gls_traj_next(t, &q, err, sizeof err) == 1);
    CHECK(q.frame == 5 && q.time == 0.2 && q.R[1] == -1 && q.R[3] == 1 && q.T[2] == 3000 && q.line == 4);
    CHECK(gls_traj_next(t, &q, err, sizeof err) == 1);
    CHECK(q.frame == 7 && q.T[2] == 0.30000000000000004);
    CHECK(gls_traj_next(t, &q, err, sizeof err) == 0);
    gls_traj_close(t);
}

static void expect_error(const char *name, const char *text, const char *want)
{
    const char *p = write_file(name, text);
    char err[512] = "", full[512];
    gls_traj_pose q;
    long n = read_all(p, &q, err, sizeof err);
    snprintf(full, sizeof full, "%s/%s", dir, want);
    CHECK_MSG(n == -1 && strcmp(err, full) == 0, "%s: got '%s'\n    wanted '%s'", name, err, full);
}

static void test_errors(void)
{
    const char *I = "1 0 0 0 1 0 0 0 1";
    char t[512];
    snprintf(t, sizeof t, "0 0 %s 0 0 0\n1 0.04 %s 0 0\n", I, I);
    expect_error("count.txt", t, "count.txt:2: error: expected 14 values (frame time R[9] T[3]), got 13");
    snprintf(t, sizeof t, "0 0 %s 0 0 0 9\n", I);
    expect_error("count2.txt", t,
                 "count2.txt:1: error: expected 14 values (frame time R[9] T[3]), 12 (KITTI: [R|t] row-major) or 8 "
                 "(TUM: time tx ty tz qx qy qz qw), got more than 14");
    expect_error("kitti_count.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n",
                 "kitti_count.txt:2: error: expected 12 values (KITTI, like the first line: [R|t] row-major), got 11");
    expect_error("tum_quat.txt", "0.5 1 2 3 0 0 0 1\n0.6 1 2 3 0 0 0.1 1\n",
                 "tum_quat.txt:2: error: quaternion (0 0 0.1 1) is not of unit length");
    expect_error("tum_time.txt", "0.5 1 2 3 0 0 0 1\n0.5 1 2 3 0 0 0 1\n",
                 "tum_time.txt:2: error: time 0.5 is not after the previous frame's 0.5");
    expect_error("kitti_mirror.txt", "-1 0 0 0 0 1 0 0 0 0 1 0\n",
                 "kitti_mirror.txt:1: error: R has determinant -1; a rotation needs +1 (a reflection swaps handedness)");
    snprintf(t, sizeof t, "-1 0 %s 0 0 0\n", I);
    expect_error("neg.txt", t, "neg.txt:1: error: frame '-1' is not a whole number");
    snprintf(t, sizeof t, "1.5 0 %s 0 0 0\n", I);
    expect_error("frac.txt", t, "frac.txt:1: error: frame '1.5' is not a whole number");
    snprintf(t, sizeof t, "0 0 %s 0 nan 0\n", I);
    expect_error("nan.txt", t, "nan.txt:1: error: value 13 ('nan') is not a finite number");
    snprintf(t, sizeof t, "0 0 %s 0 0 1e999\n", I);
    expect_error("inf.txt", t, "inf.txt:1: error: value 14 ('1e999') is too large for a double (magnitudes up to 1.8e308)");
    snprintf(t, sizeof t, "0 0 %s 1e-320 0 0\n", I);
    expect_error("tiny.txt", t,
                 "tiny.txt:1: error: value 12 ('1e-320') is too close to zero for a double (nonzero magnitudes from 2.2e-308)");
    snprintf(t, sizeof t, "3 0 %s 0 0 0\n# c\n3 1 %s 0 0 0\n", I, I);
    expect_error("order.txt", t, "order.txt:3: error: frame 3 does not follow frame 3: frames must increase");
    snprintf(t, sizeof t, "3 1 %s 0 0 0\n4 1 %s 0 0 0\n", I, I);
    expect_error("time.txt", t, "time.txt:2: error: time 1 is not after the previous frame's 1");
    expect_error("scaled.txt", "0 0 1.001 0 0 0 1 0 0 0 1 0 0 0\n",
                 "scaled.txt:1: error: R is not orthonormal: (R R^T)[0][0] = 1.002001, must be 1 within 1e-4");
    expect_error("mirror.txt", "0 0 -1 0 0 0 1 0 0 0 1 0 0 0\n",
                 "mirror.txt:1: error: R has determinant -1; a rotation needs +1 (a reflection swaps handedness)");
    expect_error("empty.txt", "# nothing\n", "empty.txt:1: error: no frames in the trajectory");
    char err[512];
    snprintf(t, sizeof t, "%s/none.txt", dir);
    CHECK(gls_traj_open(t, NULL, err, sizeof err) == NULL);
    CHECK_MSG(strstr(err, "none.txt: error: cannot open: No such file") != NULL, "%s", err);
}

/* KITTI and TUM rows give the camera's pose in the world (P_world = Rw
 * P_cam + c); the reader turns them into world -> rig poses, R = Rw^T,
 * T = -Rw^T c, numbering frames by row.  The rows here are written from
 * known world -> rig poses (R, T) by the test's own arithmetic, the
 * quaternion by the matrix -> quaternion direction (the reader goes the
 * other way), and must read back as (R, T). */
static void test_kitti_tum(void)
{
    double R[3][9], T[3][3];
    double r0[3] = {0.3, -1.1, 0.7}, r1[3] = {-2.5, 0.4, 0.2}, r2[3] = {0.01, 3.0, -0.05}; /* angle near pi too */
    gls_rotation_rodrigues(r0, R[0]), gls_rotation_rodrigues(r1, R[1]), gls_rotation_rodrigues(r2, R[2]);
    double Tv[3][3] = {{1.5, -2, 30}, {1e6, 2e6, -3.5}, {0, 0, 0.25}};
    char kitti[2048] = "# KITTI\n", tum[2048] = "# TUM\n";
    for (int k = 0; k < 3; k++) {
        double Rw[9], c[3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Rw[3 * i + j] = R[k][3 * j + i];
        for (int i = 0; i < 3; i++)
            c[i] = -(Rw[3 * i] * Tv[k][0] + Rw[3 * i + 1] * Tv[k][1] + Rw[3 * i + 2] * Tv[k][2]);
        memcpy(T[k], Tv[k], sizeof T[k]);
        char line[512];
        snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", Rw[0],
                 Rw[1], Rw[2], c[0], Rw[3], Rw[4], Rw[5], c[1], Rw[6], Rw[7], Rw[8], c[2]);
        strcat(kitti, line);
        /* matrix -> quaternion (Shepperd: from the largest of w, x, y, z) */
        double tr = Rw[0] + Rw[4] + Rw[8], q[4]; /* x y z w */
        if (tr > 0) {
            double S = sqrt(tr + 1) * 2;
            q[3] = S / 4, q[0] = (Rw[7] - Rw[5]) / S, q[1] = (Rw[2] - Rw[6]) / S, q[2] = (Rw[3] - Rw[1]) / S;
        } else if (Rw[0] > Rw[4] && Rw[0] > Rw[8]) {
            double S = sqrt(1 + Rw[0] - Rw[4] - Rw[8]) * 2;
            q[3] = (Rw[7] - Rw[5]) / S, q[0] = S / 4, q[1] = (Rw[1] + Rw[3]) / S, q[2] = (Rw[2] + Rw[6]) / S;
        } else if (Rw[4] > Rw[8]) {
            double S = sqrt(1 + Rw[4] - Rw[0] - Rw[8]) * 2;
            q[3] = (Rw[2] - Rw[6]) / S, q[0] = (Rw[1] + Rw[3]) / S, q[1] = S / 4, q[2] = (Rw[5] + Rw[7]) / S;
        } else {
            double S = sqrt(1 + Rw[8] - Rw[0] - Rw[4]) * 2;
            q[3] = (Rw[3] - Rw[1]) / S, q[0] = (Rw[2] + Rw[6]) / S, q[1] = (Rw[5] + Rw[7]) / S, q[2] = S / 4;
        }
        snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", 100.25 + 0.1 * k, c[0], c[1],
                 c[2], q[0], q[1], q[2], q[3]);
        strcat(tum, line);
    }
    const char *paths[2] = {NULL, NULL};
    char kp[160], tp[160];
    snprintf(kp, sizeof kp, "%s", write_file("kitti.txt", kitti));
    snprintf(tp, sizeof tp, "%s", write_file("tum.txt", tum));
    paths[0] = kp, paths[1] = tp;
    for (int f = 0; f < 2; f++) {
        char err[512];
        gls_traj *t = gls_traj_open(paths[f], NULL, err, sizeof err);
        CHECK(t != NULL);
        gls_traj_pose p;
        for (int k = 0; k < 3; k++) {
            CHECK_MSG(gls_traj_next(t, &p, err, sizeof err) == 1, "%s", err);
            CHECK(p.frame == (uint64_t)k && p.line == (unsigned)k + 2);
            CHECK(f == 0 ? p.time == k : fabs(p.time - (100.25 + 0.1 * k)) < 1e-12);
            double e = 0;
            for (int i = 0; i < 9; i++)
                e = fmax(e, fabs(p.R[i] - R[k][i]));
            /* T comes back through -Rw^T c: rounding relative to |T| */
            double n = sqrt(T[k][0] * T[k][0] + T[k][1] * T[k][1] + T[k][2] * T[k][2]);
            for (int i = 0; i < 3; i++)
                e = fmax(e, fabs(p.T[i] - T[k][i]) / fmax(1, n));
            CHECK_MSG(e < 1e-12, "%s frame %d: largest difference %g", f ? "TUM" : "KITTI", k, e);
        }
        CHECK(gls_traj_next(t, &p, err, sizeof err) == 0);
        gls_traj_close(t);
    }
}

/* Rotations printed with 5 decimals are re-orthonormalised, with one note
   per file (at the first such line); beyond 1e-4 they are refused. */
static void test_rotation_tolerance(void)
{
    const char *R5 = "0.91839 -0.23599 0.3176  0.3176 0.91839 -0.23599  -0.23599 0.3176 0.91839";
    char text[512], err[512] = "", *notes = NULL;
    size_t nlen = 0;
    snprintf(text, sizeof text, "0 0 1 0 0 0 1 0 0 0 1 0 0 0\n1 0.1 %s 0 0 0\n2 0.2 %s 1 2 3\n", R5, R5);
    const char *p = write_file("r5.txt", text);
    FILE *nf = open_memstream(&notes, &nlen);
    gls_traj *t = gls_traj_open(p, nf, err, sizeof err);
    CHECK(t != NULL);
    gls_traj_pose q;
    int n = 0, r;
    double worst = 0;
    while (t && (r = gls_traj_next(t, &q, err, sizeof err)) == 1) {
        n++;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                worst = fmax(worst, fabs(q.R[3 * i] * q.R[3 * j] + q.R[3 * i + 1] * q.R[3 * j + 1] +
                                         q.R[3 * i + 2] * q.R[3 * j + 2] - (i == j)));
    }
    gls_traj_close(t);
    fclose(nf);
    CHECK_MSG(n == 3, "%d frames: %s", n, err);
    CHECK_MSG(worst < 1e-15, "R R^T - I up to %g", worst);
    char want[256];
    snprintf(want, sizeof want, "%s:2: note: R is orthonormal only within ", p);
    CHECK_MSG(notes && strncmp(notes, want, strlen(want)) == 0 && strchr(notes, '\n') == notes + nlen - 1, "'%s'",
              notes ? notes : "");
    free(notes);
}

/* Compose against transforming a point in two steps. */
static void test_compose(void)
{
    double a = 0.3, b = -1.1;
    double Rc[9] = {cos(a), 0, sin(a), 0, 1, 0, -sin(a), 0, cos(a)}, Tc[3] = {0.15, -0.02, 0.4};
    double Rr[9] = {1, 0, 0, 0, cos(b), -sin(b), 0, sin(b), cos(b)}, Tr[3] = {-1e4, 3.5, 2e4};
    double R[9], T[3];
    gls_traj_compose(Rc, Tc, Rr, Tr, R, T);
    double P[3] = {1e4 + 3, 12, -2e4 + 7}, Pr[3], Pc[3], Pd[3];
    for (int i = 0; i < 3; i++)
        Pr[i] = Rr[3 * i] * P[0] + Rr[3 * i + 1] * P[1] + Rr[3 * i + 2] * P[2] + Tr[i];
    for (int i = 0; i < 3; i++)
        Pc[i] = Rc[3 * i] * Pr[0] + Rc[3 * i + 1] * Pr[1] + Rc[3 * i + 2] * Pr[2] + Tc[i];
    for (int i = 0; i < 3; i++)
        Pd[i] = R[3 * i] * P[0] + R[3 * i + 1] * P[1] + R[3 * i + 2] * P[2] + T[i];
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(Pd[i], Pc[i], 1e-9);
    char why[300];
    CHECK(gls_rotation_check(R, why, sizeof why) == 0);
    /* identity camera: the rig's pose itself */
    double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, Z[3] = {0, 0, 0};
    gls_traj_compose(I, Z, Rr, Tr, R, T);
    CHECK(memcmp(R, Rr, sizeof R) == 0 && memcmp(T, Tr, sizeof T) == 0);
}

static void test_range(void)
{
    uint64_t a, b;
    char err[256];
    CHECK(gls_traj_range("100:200", &a, &b, err, sizeof err) == 0 && a == 100 && b == 200);
    CHECK(gls_traj_range("100:", &a, &b, err, sizeof err) == 0 && a == 100 && b == UINT64_MAX);
    CHECK(gls_traj_range(":50", &a, &b, err, sizeof err) == 0 && a == 0 && b == 50);
    CHECK(gls_traj_range("7", &a, &b, err, sizeof err) == 0 && a == 7 && b == 8);
    CHECK(gls_traj_range("5:5", &a, &b, err, sizeof err) == -1);
    CHECK_STR(err, "--frames: '5:5' is empty (A:B means frames A to B-1)");
    CHECK(gls_traj_range(":", &a, &b, err, sizeof err) == -1);
    CHECK(gls_traj_range("1:2:3", &a, &b, err, sizeof err) == -1);
    CHECK(gls_traj_range("-1:3", &a, &b, err, sizeof err) == -1);
    CHECK(gls_traj_range("x", &a, &b, err, sizeof err) == -1);
    CHECK_STR(err, "--frames: 'x' is not a frame range (A:B for frames A to B-1, A:, :B, or A)");
}

/* A line is read only up to GLS_TEXT_MAX_LINE bytes: a longer one is an
   error at its line, and one that never ends costs no memory. */
static void test_line_bound(void)
{
    const char *I = "1 0 0 0 1 0 0 0 1";
    static char t[3 * GLS_TEXT_MAX_LINE];
    /* exactly at the limit: read */
    int k = snprintf(t, sizeof t, "0 0 %s 0 0 0 #", I);
    memset(t + k, 'c', GLS_TEXT_MAX_LINE - (size_t)k);
    strcpy(t + GLS_TEXT_MAX_LINE, "\n");
    const char *p = write_file("at_limit.txt", t);
    char err[512] = "";
    gls_traj_pose q;
    CHECK_MSG(read_all(p, &q, err, sizeof err) == 1, "%s", err);
    /* one byte more, on line 2 */
    k = snprintf(t, sizeof t, "0 0 %s 0 0 0\n1 1 %s 0 0 0 #", I, I);
    memset(t + k, 'c', 2 * GLS_TEXT_MAX_LINE);
    strcpy(t + 2 * GLS_TEXT_MAX_LINE, "\n");
    expect_error("long.txt", t, "long.txt:2: error: line longer than 4095 bytes");
    /* no newline at all: 1 GiB of zeros (a sparse file; inputs are regular
       files, so /dev/zero is refused before any of it is read) */
    p = write_file("zeros.txt", "");
    CHECK(truncate(p, 1 << 30) == 0);
    char want[300];
    snprintf(want, sizeof want, "%s:1: error: line longer than 4095 bytes", p);
    struct rusage r0, r1;
    getrusage(RUSAGE_SELF, &r0);
    CHECK(read_all(p, &q, err, sizeof err) == -1);
    getrusage(RUSAGE_SELF, &r1);
    CHECK_STR(err, want);
    unlink(p);
    CHECK_MSG(r1.ru_maxrss - r0.ru_maxrss < 1024, "peak RSS grew by %ld kB", r1.ru_maxrss - r0.ru_maxrss);
}

/* 20000 frames (a file of ~3 MB): read once, whole (its bytes are the
   memory it takes), then parsed from memory by a reader that holds one
   line, so parsing it, as often as a run does, adds nothing. */
static void test_streaming(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/long.txt", dir);
    FILE *f = fopen(path, "w");
    for (long k = 0; k < 20000; k++) {
        double a = k * 1e-3;
        fprintf(f, "%ld %.17g %.17g %.17g 0 %.17g %.17g 0 0 0 1 %.17g 1.5 %.17g\n", k, k / 25.0, cos(a), -sin(a),
                sin(a), cos(a), k * 0.1, k * 0.8);
    }
    long size = ftell(f);
    fclose(f);
    gls_traj_text tx;
    char err[256];
    CHECK(gls_traj_load(path, &tx, err, sizeof err) == 0);
    CHECK(tx.len == (size_t)size && tx.data[tx.len] == 0);
    struct rusage r0, r1;
    getrusage(RUSAGE_SELF, &r0);
    for (int pass = 0; pass < 3; pass++) {
        gls_traj *t = gls_traj_open_text(&tx, NULL);
        gls_traj_pose q;
        long n = 0;
        int r;
        while ((r = gls_traj_next(t, &q, err, sizeof err)) == 1)
            n++;
        gls_traj_close(t);
        CHECK(r == 0 && n == 20000 && q.frame == 19999);
    }
    getrusage(RUSAGE_SELF, &r1);
    CHECK_MSG(r1.ru_maxrss - r0.ru_maxrss < 1024, "peak RSS grew by %ld kB", r1.ru_maxrss - r0.ru_maxrss);
    gls_traj_text_free(&tx);
}

/* A pipe is refused before anything is read (every input is a regular
   file, readfile.h): with no writer it would block the run, and what it
   says names what it is.  The file is read once into memory (so no
   reader reads it twice): test_streaming. */
static void test_pipe(void)
{
    int fd[2];
    CHECK(pipe(fd) == 0);
    const char *rows = "0 0 1 0 0 0 1 0 0 0 1 0 0 0\n";
    CHECK(write(fd[1], rows, strlen(rows)) == (ssize_t)strlen(rows));
    char path[64], err[256] = "";
    snprintf(path, sizeof path, "/dev/fd/%d", fd[0]);
    gls_traj_text tx;
    CHECK(gls_traj_load(path, &tx, err, sizeof err) == -1);
    CHECK_MSG(strstr(err, "it is a FIFO (named pipe), not a regular file") != NULL, "%s", err);
    close(fd[0]);
    close(fd[1]);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/test_road_traj.XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    RUN(test_read);
    RUN(test_errors);
    RUN(test_kitti_tum);
    RUN(test_rotation_tolerance);
    RUN(test_compose);
    RUN(test_range);
    RUN(test_streaming);
    RUN(test_pipe);
    RUN(test_line_bound);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        return 1;
    CHECK_EXIT();
}
