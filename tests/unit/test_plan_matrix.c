/* The run is its plan (runtime/play/frame_plan.h, issue 27): over a
 * matrix of options (--aa 1 and 4, each pattern; a plain camera, a lens,
 * shutter, line_delay, aperture and focus, sensor noise, a Bayer mosaic
 * with and without noise; several sets of outputs), what --explain states for a camera (the passes, whether there
 * is an accumulator and of how many samples, the buffers and their sum)
 * is what the run did, counted where it draws and allocates
 * (gls_play_opts.counts), never derived from the plan; and the files
 * explain names (from the output table's rows) are the files written.  The writer's
 * buffers (disparity, 16-bit codes, the file being encoded) are estimates
 * of the writer's work, not the frame's allocations, and are left out of
 * the byte comparison. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "player.h"
#include "player_scene.h"
#include "units.h"

static char dir[] = "/tmp/gls_plan_matrix_XXXXXX";
static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

/* the text of f, from the start */
static char *slurp(FILE *f)
{
    long n = ftell(f);
    char *s = malloc((size_t)n + 1);
    rewind(f);
    size_t got = s ? fread(s, 1, (size_t)n, f) : 0;
    if (s)
        s[got] = 0;
    return s;
}

/* the line of text that starts with prefix, into line (without the
 * newline); 0, or -1 when there is none */
static int find_line(const char *text, const char *prefix, char *line, size_t len)
{
    for (const char *p = text; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL)
        if (strncmp(p, prefix, strlen(prefix)) == 0) {
            size_t k = strcspn(p, "\n");
            snprintf(line, len, "%.*s", (int)k, p);
            return 0;
        }
    return -1;
}

typedef struct {
    const char *name;
    const char *keys; /* appended to the camera file */
} cam_case;

typedef struct {
    const char *name;
    unsigned outputs;
} out_case;

/* One run: explain and render camera c with options aa (n, pattern) and
 * outputs; compare. */
static void run_case(const char *bpath, const char *traj, const cam_case *cc, uint32_t n, gls_aa_pattern pattern,
                     int exact, const out_case *oc)
{
    char cpath[512], outdir[512], label[256];
    snprintf(cpath, sizeof cpath, "%s/%s.cam", dir, cc->name);
    snprintf(outdir, sizeof outdir, "%s/out", dir);
    snprintf(label, sizeof label, "camera %s, --aa %u %s%s, outputs %s", cc->name, n, gls_aa_pattern_name(pattern),
             exact ? " exact" : "", oc->name);
    const char *cams[1] = {cpath};
    gls_frame_counts counts;
    gls_play_opts o;
    memset(&o, 0, sizeof o);
    o.bundle = bpath, o.cameras = cams, o.ncameras = 1, o.outdir = outdir, o.outputs = oc->outputs;
    o.aa = gls_aa_defaults();
    o.aa.n = n, o.aa.pattern = pattern, o.aa.exact = exact;
    o.trajectory = traj;
    o.frame_first = 1, o.frame_end = 2; /* frame 1: rows on both sides (the shutter's span, flow) */
    o.explain = 1;
    o.counts = &counts;
    FILE *errs = tmpfile(), *outs = tmpfile();
    int rc = gls_play(&o, outs, errs);
    char *plan = slurp(outs), *err = slurp(errs);
    fclose(outs), fclose(errs);
    CHECK_MSG(rc == 0 && plan && err, "%s: exit %d: %s", label, rc, err ? err : "");
    if (rc || !plan) {
        free(plan), free(err);
        return;
    }
    char line[1024], want[1024];
    /* passes */
    CHECK_MSG(find_line(plan, "  frame plan: passes", line, sizeof line) == 0, "%s: no frame plan line", label);
    int len = snprintf(want, sizeof want, "  frame plan: passes");
    for (int k = 0; k < GLS_PASS_COUNT; k++)
        if (counts.passes[k])
            len += snprintf(want + len, sizeof want - (size_t)len, " %s", gls_pass_word[k]);
    if (len == (int)strlen("  frame plan: passes"))
        snprintf(want + len, sizeof want - (size_t)len, " none");
    CHECK_MSG(strcmp(line, want) == 0, "%s: explain says '%s', the run drew '%s'", label, line, want);
    /* the accumulator */
    if (counts.accum_samples) {
        snprintf(want, sizeof want, "  accumulator: %llu samples per pixel", (unsigned long long)counts.accum_samples);
        CHECK_MSG(find_line(plan, want, line, sizeof line) == 0, "%s: the run accumulated %llu samples: %s", label,
                  (unsigned long long)counts.accum_samples, plan);
        CHECK_MSG(!strstr(plan, "no accumulator"), "%s: explain says no accumulator", label);
    } else {
        CHECK_MSG(strstr(plan, "no accumulator") && !strstr(plan, "  accumulator:"),
                  "%s: the run accumulated nothing, explain says otherwise", label);
    }
    /* the buffers the frame allocated, each as explain names it, and
     * explain's exact sum less the writer's part is the run's */
    CHECK_MSG(find_line(plan, "  buffers:", line, sizeof line) == 0, "%s: no buffers line", label);
    uint64_t sum = 0;
    for (int k = 0; k < GLS_BUF_COUNT; k++) {
        if (k == GLS_BUF_DISPARITY || k == GLS_BUF_CODES16 || k == GLS_BUF_ENCODE)
            continue; /* the writer's */
        char bytes[32], item[96], item2[96];
        sum += counts.bytes[k];
        gls_fmt_bytes(bytes, sizeof bytes, counts.bytes[k]);
        /* a buffer's words follow the line's colon or a comma: "colour"
         * is not "exact colour" */
        snprintf(item, sizeof item, ": %s %s", gls_buffer_word[k], bytes);
        snprintf(item2, sizeof item2, ", %s %s", gls_buffer_word[k], bytes);
        if (counts.bytes[k])
            CHECK_MSG(strstr(line, item) || strstr(line, item2), "%s: the run allocated %s of %s: %s", label, bytes,
                      gls_buffer_word[k], line);
        snprintf(item, sizeof item, ": %s ", gls_buffer_word[k]);
        snprintf(item2, sizeof item2, ", %s ", gls_buffer_word[k]);
        if (!counts.bytes[k])
            CHECK_MSG(!strstr(line, item) && !strstr(line, item2), "%s: explain names %s, the run allocated none: %s",
                      label, gls_buffer_word[k], line);
    }
    unsigned long long total = 0, writer = 0;
    const char *at = strstr(line, " in all (");
    CHECK_MSG(at && sscanf(at, " in all (%llu bytes, %llu of them the writer's)", &total, &writer) == 2,
              "%s: no exact total: %s", label, line);
    CHECK_MSG(total - writer == sum, "%s: explain's %llu bytes less the writer's %llu, the run's %llu: %s", label,
              total, writer, (unsigned long long)sum, line);
    /* the files: each the files line names was written, and no other */
    CHECK_MSG(find_line(plan, "  files:", line, sizeof line) == 0, "%s: no files line", label);
    for (int k = 0; k < GLS_OUT_KINDS; k++) {
        const gls_output_kind *row = &gls_output_kinds[k];
        char item[96], path[700];
        snprintf(item, sizeof item, " %s_F.%s (", row->stem, row->ext ? row->ext : "pfm");
        snprintf(path, sizeof path, "%s/%s/%s_000001.%s", outdir, cc->name, row->stem, row->ext ? row->ext : "pfm");
        int named = strstr(line, item) != NULL, written = access(path, F_OK) == 0;
        CHECK_MSG(named == written, "%s: %s %s by explain, %s by the run", label, path, named ? "named" : "not named",
                  written ? "written" : "not written");
    }
    char rm[700];
    snprintf(rm, sizeof rm, "rm -rf '%s'", outdir);
    if (system(rm) != 0)
        printf("  could not remove %s\n", outdir);
    free(plan), free(err);
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    return fclose(f);
}

/* Every case of the matrix, explained and run. */
static void test_plan_matrix(void)
{
    /* a quad 5 units ahead, two colours (mixed pixels at its edges) */
    tb t;
    tb_init(&t);
    tb_object(&t, "top", 1);
    tb_rect_z(&t, -1, -1, 1, 1, 5);
    gls_bundle *b = tb_finish(&t);
    char bpath[512], traj[512];
    snprintf(bpath, sizeof bpath, "%s/s.glsb", dir);
    snprintf(traj, sizeof traj, "%s/t.txt", dir);
    CHECK(tb_write(b, bpath) == 0);
    /* four frames; the rig moves a little along x */
    CHECK(write_text(traj, "0 0 1 0 0 0 1 0 0 0 1 0 0 0\n"
                           "1 1 1 0 0 0 1 0 0 0 1 0.05 0 0\n"
                           "2 2 1 0 0 0 1 0 0 0 1 0.1 0 0\n"
                           "3 3 1 0 0 0 1 0 0 0 1 0.15 0 0\n") == 0);
    static const cam_case cams[] = {
        {"plain", ""},
        {"lens", "distortion 0.05 0 0 0\n"},
        {"shutter", "shutter 0.5\nexposure_samples 4\n"},
        {"rolling", "line_delay 0.001\n"},
        {"dof", "aperture 0.2\nfocus 5\nexposure_samples 4\n"},
        {"sensor", "shot_noise 1000\nread_noise 0.01\n"},
        {"bayer", "bayer RGGB\nread_noise 0.01\n"},
        {"mosaic", "bayer GBRG\n"},
    };
    double Tc[3] = {0, 0, 0};
    gls_camera c = tb_camera(32, 24, 30, 30, 15.5, 11.5, 0, I3, Tc, 0.1, 100);
    for (size_t i = 0; i < sizeof cams / sizeof cams[0]; i++) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.cam", dir, cams[i].name);
        CHECK(tb_write_camera(&c, path) == 0);
        FILE *f = fopen(path, "a");
        CHECK(f && fprintf(f, "pose rig\n%s", cams[i].keys) >= 0 && fclose(f) == 0);
    }
    static const out_case outs[] = {
        {"image", GLS_OUT_IMAGE},
        {"image,depth,edges", GLS_OUT_IMAGE | GLS_OUT_DEPTH | GLS_OUT_EDGES},
        {"instance,normals", GLS_OUT_INSTANCE | GLS_OUT_NORMALS},
        {"points,flow,boxes,landmarks", GLS_OUT_POINTS | GLS_OUT_FLOW_ALL | GLS_OUT_BOXES_ALL | GLS_OUT_LANDMARKS},
    };
    static const struct {
        uint32_t n;
        gls_aa_pattern pattern;
    } aas[] = {{1, GLS_AA_LATTICE}, {4, GLS_AA_LATTICE}, {4, GLS_AA_GRID}, {4, GLS_AA_STRATIFIED}};
    int runs = 0;
    for (size_t a = 0; a < sizeof aas / sizeof aas[0]; a++)
        for (size_t i = 0; i < sizeof cams / sizeof cams[0]; i++)
            for (size_t k = 0; k < sizeof outs / sizeof outs[0]; k++) {
                run_case(bpath, traj, &cams[i], aas[a].n, aas[a].pattern, 0, &outs[k]);
                runs++;
            }
    /* exact coverage: a pinhole without effects (the others are refused),
     * and its coverage output */
    static const out_case cover = {"image,coverage", GLS_OUT_IMAGE | GLS_OUT_COVERAGE},
                          cover_only = {"coverage", GLS_OUT_COVERAGE},
                          segs = {"image,edge_segments", GLS_OUT_IMAGE | GLS_OUT_EDGE_SEGMENTS},
                          segs_only = {"edge_segments", GLS_OUT_EDGE_SEGMENTS};
    for (size_t k = 0; k < sizeof outs / sizeof outs[0]; k++) {
        run_case(bpath, traj, &cams[0], 1, GLS_AA_LATTICE, 1, &outs[k]);
        runs++;
    }
    run_case(bpath, traj, &cams[0], 1, GLS_AA_LATTICE, 1, &cover);
    run_case(bpath, traj, &cams[0], 1, GLS_AA_LATTICE, 1, &cover_only);
    run_case(bpath, traj, &cams[0], 1, GLS_AA_LATTICE, 1, &segs);
    run_case(bpath, traj, &cams[0], 1, GLS_AA_LATTICE, 1, &segs_only);
    runs += 4;
    printf("  %d runs: explain's passes, accumulator, buffers and files against the run's\n", runs);
    gls_bundle_free(b);
}

/* gls_play refuses coverage without exact coverage before drawing (its
 * callers other than glsplay's arguments reach it too) */
static void test_coverage_needs_exact(void)
{
    gls_play_opts o;
    char msg[256] = "";
    memset(&o, 0, sizeof o);
    o.aa = gls_aa_defaults();
    o.outputs = GLS_OUT_IMAGE | GLS_OUT_COVERAGE;
    CHECK(gls_play_check_options(&o, msg, sizeof msg) == -1);
    CHECK_STR(msg, "--outputs coverage needs --aa exact (exact areas, no samples)");
    o.aa.exact = 1;
    CHECK(gls_play_check_options(&o, msg, sizeof msg) == 0);
    /* edge_segments likewise, named by itself */
    o.aa.exact = 0;
    o.outputs = GLS_OUT_IMAGE | GLS_OUT_EDGE_SEGMENTS;
    CHECK(gls_play_check_options(&o, msg, sizeof msg) == -1);
    CHECK_STR(msg, "--outputs edge_segments needs --aa exact (exact areas, no samples)");
    o.aa.exact = 1;
    CHECK(gls_play_check_options(&o, msg, sizeof msg) == 0);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        printf("FAIL test_plan_matrix: mkdtemp\n");
        return 1;
    }
    RUN(test_plan_matrix);
    RUN(test_coverage_needs_exact);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("  could not remove %s\n", dir);
    CHECK_EXIT();
}
