/* The flow of one camera frame (play_int.h): the next row's depth drawn
 * (whole, or row by row under a rolling shutter; through the lens when
 * there is one) and the flow from this frame's ground truth to it. */
#include <math.h>
#include <stdlib.h>
#include "gt_flow_rolling.h"
#include "gt_pass.h"
#include "lens_truth.h"
#include "numfmt.h"
#include "out_flow.h"
#include "play_int.h"

static int flow_frame_rolling(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name,
                              uint32_t frame, gls_bands bands, const uint32_t *inst, const float *z, float *z1, float *uv,
                              uint8_t *mask, char *msg, size_t msglen);

/* The flow of camera c from frame to the trajectory's next row (gt_flow.h),
 * from this frame's ground-truth pass (inst, z): the depth of the next
 * (its camera pose and motions; an extra centre pass), then the scene
 * posed back for this frame's other cameras.  0 with *uv and *mask, or -1
 * with the whole line in msg (empty: out of memory). */
int play_flow_frame(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name, uint32_t frame,
                    gls_bands bands,
                    const uint32_t *inst, const float *z, float **uv, uint8_t **mask, char *msg, size_t msglen)
{
    size_t n = (size_t)c->width * c->height;
    float *z1 = malloc(n * sizeof *z1);
    char err[512];
    int rc = -1;
    *uv = malloc(2 * n * sizeof **uv);
    *mask = malloc(n ? n : 1);
    if (!z1 || !*uv || !*mask)
        goto out;
    if (s->counts)
        s->counts->bytes[GLS_BUF_FLOW] += n * sizeof *z1 + 2 * n * sizeof **uv + n,
            s->counts->passes[GLS_PASS_I_FLOW_NEXT]++;
    if (bands.rows < c->height) {
        /* rolling shutter: both frames' rows at their own times (a lens,
         * df: their points projected by its model) */
        rc = flow_frame_rolling(s, c, df, name, frame, bands, inst, z, z1, *uv, *mask, msg, msglen);
        if (rc)
            goto out;
        goto check;
    }
    gls_camera c1 = *c;
    gls_traj_compose(s->rel->R, s->rel->T, s->next->R, s->next->T, c1.R, c1.T);
    gls_flow_moves_take(s->moves, s->ms->scene, 0);
    if (s->ms->n) {
        play_motion_apply(s->ms, s->next->frame);
        gls_flow_moves_take(s->moves, s->ms->scene, 1);
    }
    /* a lens (df): the next frame's depth through it, its points projected by its model */
    rc = df ? gls_lens_gt_render(s->r, df, &c1, NULL, NULL, z1, err, sizeof err)
            : gls_gt_render(s->r, &c1, NULL, NULL, z1, err, sizeof err);
    if (s->ms->n)
        play_motion_apply(s->ms, frame);
    if (rc) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", name, err);
        goto out;
    }
    if (df)
        gls_flow_compute_lens(c, &c1, df, inst, z, z1, s->moves, *uv, *mask);
    else
        gls_flow_compute(c, &c1, inst, z, z1, s->moves, *uv, *mask);
check:;
    uint32_t x, y;
    float fu, fv;
    if ((s->o->outputs & GLS_OUT_FLOW) && gls_flow_kitti_check(*uv, *mask, c->width, c->height, &x, &y, &fu, &fv)) {
        int along_u = !(fabsf(fv) > fabsf(fu));
        snprintf(msg, msglen,
                 "glsplay: error: camera %s, frame %u: the flow at pixel (%u, %u) moves %.2f px along %c, beyond the "
                 "-512..512 px a KITTI flow PNG holds; leave out flow or move less between frames",
                 name, frame, x, y, along_u ? fu : fv, along_u ? 'u' : 'v');
        rc = -1;
    }
out:
    free(z1);
    if (rc) {
        free(*uv);
        free(*mask);
        *uv = NULL, *mask = NULL;
    }
    return rc;
}

/* play_flow_frame with a rolling shutter (gt_flow_rolling.h): the poses of
 * every row of this frame and the next, the next frame's rolling depth
 * (through df's lens when df).  0, or -1 with the whole line in msg
 * (empty: out of memory). */
static int flow_frame_rolling(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name,
                              uint32_t frame, gls_bands bands, const uint32_t *inst, const float *z, float *z1, float *uv,
                              uint8_t *mask, char *msg, size_t msglen)
{
    double dt = (double)s->next->frame - (double)frame, bad = 0;
    char err[512];
    gls_flow_rows fr;
    int k = gls_flow_rows_fill(&fr, c, bands.rows, dt, s->moves, s->ms->scene, play_pose_at, s, &bad);
    if (k == 1) {
        char a[40];
        gls_fmt_double(a, sizeof a, (double)frame + bad);
        snprintf(msg, msglen, "glsplay: error: camera %s, frame %u: its flow needs the poses of the rolling readout "
                              "of frame %llu, at frame %s beyond the rows of the trajectory or a motion file; sub-frame "
                              "poses are interpolated between rows, never extrapolated: render fewer --frames or "
                              "extend the file", name, frame, (unsigned long long)s->next->frame, a);
        return -1;
    }
    if (k)
        return -1;
    if (gls_flow_rolling_depth(s->r, c, df, bands, dt, play_pose_at, s, z1, err, sizeof err)) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", name, err);
        gls_flow_rows_free(&fr);
        return -1;
    }
    gls_flow_compute_rolling(c, df, &fr, s->moves, inst, z, z1, uv, mask);
    gls_flow_rows_free(&fr);
    return 0;
}
