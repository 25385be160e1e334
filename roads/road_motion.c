/* Motion along the road: speed profiles, the body's pitch and heave (a
 * damped spring-mass model driven by the road), the rig's pose per frame,
 * other vehicles, and the trajectory outputs (spec/road.md).
 *
 * Over 500 lines because its parts are one computation: the per-frame
 * walk (road_run_trajectory) advances the speed profile, the road's
 * roughness and the body's state together and composes the rig's pose
 * from them; the vehicles reuse the profiles and the pose composition,
 * and the writers are the walk's only callers.  Each part is a few
 * static functions, in that order. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "road.h"

#define DEG (M_PI / 180)

/* log(1 + q) / q, continuous at q = 0 */
static double log1p_over(double q) { return q == 0 ? 1 : log1p(q) / q; }
/* (exp(y) - 1) / y, continuous at y = 0 */
static double expm1_over(double y) { return y == 0 ? 1 : expm1(y) / y; }

void road_profile_motion(const road_profile *p, double t, double *x, double *v, double *a)
{
    double X = 0;
    for (int k = 0; k + 1 < p->n; k++) {
        double v0 = p->v[k], v1 = p->v[k + 1];
        if (p->by_time) {
            double t0 = p->x[k], t1 = p->x[k + 1], acc = (v1 - v0) / (t1 - t0);
            if (t < t1) {
                double tau = t - t0;
                *x = X + v0 * tau + 0.5 * acc * tau * tau;
                *v = v0 + acc * tau;
                *a = acc;
                return;
            }
            X += 0.5 * (v0 + v1) * (t1 - t0);
        } else {
            /* v linear in distance: v = v0 + b (x - x0), so dt = dx / v and
               the segment takes T = ln(v1 / v0) / b; inverted,
               x - x0 = v0 (exp(b tau) - 1) / b, v = v0 exp(b tau). */
            double dx = p->x[k + 1] - p->x[k], b = (v1 - v0) / dx;
            double T = dx / v0 * log1p_over((v1 - v0) / v0);
            if (t < T) {
                *x = X + v0 * t * expm1_over(b * t);
                *v = v0 * exp(b * t);
                *a = b * *v;
                return;
            }
            X += dx;
            t -= T;
        }
    }
    double tl = p->by_time ? p->x[p->n - 1] : 0;
    *x = X + p->v[p->n - 1] * (t - tl);
    *v = p->v[p->n - 1];
    *a = 0;
}

double road_profile_time_to(const road_profile *p, double X)
{
    double t = 0, x = 0; /* where segment k starts */
    for (int k = 0; k + 1 < p->n; k++) {
        double v0 = p->v[k], v1 = p->v[k + 1];
        if (p->by_time) {
            double t0 = p->x[k], t1 = p->x[k + 1], acc = (v1 - v0) / (t1 - t0);
            double D = 0.5 * (v0 + v1) * (t1 - t0);
            if (X <= x + D) {
                /* v0 tau + acc tau^2 / 2 = X - x, the root that cannot
                   cancel */
                double r = X - x;
                return r <= 0 ? t0 : t0 + 2 * r / (v0 + sqrt(v0 * v0 + 2 * acc * r));
            }
            x += D;
            t = t1;
        } else {
            double dx = p->x[k + 1] - p->x[k];
            if (X <= x + dx) /* inverse of x(t) in road_profile_motion */
                return t + (X - x) / v0 * log1p_over((v1 - v0) * (X - x) / (dx * v0));
            t += dx / v0 * log1p_over((v1 - v0) / v0);
            x += dx;
        }
    }
    if (p->by_time)
        t = p->x[p->n - 1];
    double vl = p->v[p->n - 1];
    return X <= x ? t : vl > 0 ? t + (X - x) / vl : INFINITY;
}

/* ---- road roughness ----------------------------------------------------- */

#define NWAVES 32

typedef struct {
    double k[NWAVES], amp[NWAVES], phase[NWAVES];
} rough;

static uint64_t splitmix(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Wavelengths 0.3 .. 60 m, log-spaced, amplitude ~ sqrt(wavelength): a
   displacement spectrum falling as n^-2 (ISO 8608's shape), scaled so the
   profile's rms height is the given roughness.  Seeded phases. */
static void rough_init(rough *r, double rms, unsigned long seed)
{
    uint64_t s = seed;
    double sum = 0;
    for (int i = 0; i < NWAVES; i++) {
        double lambda = 0.3 * pow(200.0, (double)i / (NWAVES - 1));
        r->k[i] = 2 * M_PI / lambda;
        r->amp[i] = sqrt(lambda);
        r->phase[i] = 2 * M_PI * (double)(splitmix(&s) >> 11) / 9007199254740992.0;
        sum += 0.5 * r->amp[i] * r->amp[i];
    }
    double scale = sum > 0 ? rms / sqrt(sum) : 0;
    for (int i = 0; i < NWAVES; i++)
        r->amp[i] *= scale;
}

static double rough_at(const rough *r, double s)
{
    double h = 0;
    for (int i = 0; i < NWAVES; i++)
        h += r->amp[i] * sin(r->k[i] * s + r->phase[i]);
    return h;
}

/* ---- body dynamics ------------------------------------------------------ */

typedef struct {
    const road_desc *d;
    rough r;
    double w, z; /* natural angular frequency, damping ratio */
    double kacc; /* rad per m/s^2 */
} body;

/* Equilibrium pitch (nose down > 0) and heave the springs pull towards at
   time t: the road's slope and height between the axles, and pitch from
   longitudinal acceleration (braking dips the nose). */
static void body_input(const body *b, double t, double *th, double *hv)
{
    const road_desc *d = b->d;
    double x, v, a;
    road_profile_motion(&d->speed, t, &x, &v, &a);
    double s = d->start + x, wb = d->wheelbase;
    double rf = d->roughness > 0 ? rough_at(&b->r, s + 0.5 * wb) : 0;
    double rr = d->roughness > 0 ? rough_at(&b->r, s - 0.5 * wb) : 0;
    *th = -(rf - rr) / wb - b->kacc * a;
    *hv = 0.5 * (rf + rr);
}

/* y = (theta, theta', heave, heave'): y'' = w^2 (input - y) - 2 z w y'. */
static void body_deriv(const body *b, double t, const double y[4], double dy[4])
{
    double th, hv;
    body_input(b, t, &th, &hv);
    dy[0] = y[1];
    dy[1] = b->w * b->w * (th - y[0]) - 2 * b->z * b->w * y[1];
    dy[2] = y[3];
    dy[3] = b->w * b->w * (hv - y[2]) - 2 * b->z * b->w * y[3];
}

/* Classical RK4 from t0 to t1 in steps of at most 1 ms: deterministic, and
   far finer than the body's period (~1 s). */
static void body_step(const body *b, double t0, double t1, double y[4])
{
    int n = (int)ceil((t1 - t0) / 1e-3);
    if (n < 1)
        n = 1;
    double h = (t1 - t0) / n;
    for (int i = 0; i < n; i++) {
        double t = t0 + i * h, k1[4], k2[4], k3[4], k4[4], tmp[4];
        body_deriv(b, t, y, k1);
        for (int j = 0; j < 4; j++)
            tmp[j] = y[j] + 0.5 * h * k1[j];
        body_deriv(b, t + 0.5 * h, tmp, k2);
        for (int j = 0; j < 4; j++)
            tmp[j] = y[j] + 0.5 * h * k2[j];
        body_deriv(b, t + 0.5 * h, tmp, k3);
        for (int j = 0; j < 4; j++)
            tmp[j] = y[j] + h * k3[j];
        body_deriv(b, t + h, tmp, k4);
        for (int j = 0; j < 4; j++)
            y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
}

/* ---- poses -------------------------------------------------------------- */

static void rot_x(double a, double M[9])
{
    double c = cos(a), s = sin(a), R[9] = {1, 0, 0, 0, c, -s, 0, s, c};
    memcpy(M, R, sizeof R);
}
static void rot_y(double a, double M[9])
{
    double c = cos(a), s = sin(a), R[9] = {c, 0, s, 0, 1, 0, -s, 0, c};
    memcpy(M, R, sizeof R);
}
static void rot_z(double a, double M[9])
{
    double c = cos(a), s = sin(a), R[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    memcpy(M, R, sizeof R);
}

/* The rig's axes in body coordinates (camera convention: x right, y down,
   z forward; the body's are x left, y up, z forward):
   R_body_rig = diag(-1, -1, 1) Ry(yaw) Rx(-pitch) Rz(roll), so positive
   yaw turns right, positive pitch looks down, positive roll turns
   clockwise as seen from behind. */
static void rig_in_body(const road_desc *d, double M[9])
{
    double B[9] = {-1, 0, 0, 0, -1, 0, 0, 0, 1}, Y[9], P[9], Rr[9];
    rot_y(d->rig_yaw * DEG, Y);
    rot_x(-d->rig_pitch * DEG, P);
    rot_z(d->rig_roll * DEG, Rr);
    rm_mul(B, Y, M);
    rm_mul(M, P, M);
    rm_mul(M, Rr, M);
}

/* Pose (camera-file convention) of a frame with axes R_w (columns, in the
   world) at position p: R = R_w^T, T = -R p. */
static void to_camfile(const double Rw[9], rv3 p, double R[9], double T[3])
{
    rm_transpose(Rw, R);
    rv3 t = rm_apply(R, p);
    T[0] = -t.x;
    T[1] = -t.y;
    T[2] = -t.z;
}

typedef struct {
    const road_geo *g;
    body b;
    double Rbr[9];
} rigctx;

static void rig_pose(const rigctx *rc, const road_frame *f, double pitch, double heave, double R[9], double T[3])
{
    const road_desc *d = rc->g->d;
    double Rwv[9], Rvb[9], Rwb[9], Rwr[9];
    rm_cols(f->l, f->n, f->t, Rwv); /* vehicle axes: left, up (surface normal), forward */
    rot_x(pitch, Rvb);              /* nose down: z turns towards -y */
    rm_mul(Rwv, Rvb, Rwb);
    rm_mul(Rwb, rc->Rbr, Rwr);
    rv3 P = rv_madd(f->C, f->l, d->vehicle_lateral);
    P = rv_madd(P, f->n, heave);
    P = rv_add(P, rm_apply(Rwb, rv(d->rig_lateral, d->rig_height, d->rig_forward)));
    to_camfile(Rwr, P, R, T);
}

long road_run_trajectory(const road_geo *g, road_pose_fn fn, void *ctx, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    double L = g->c.length;
    if (d->start > L) {
        snprintf(err, errlen, "%s: error: start %g m is beyond the end of the road (%.3f m)", d->file, d->start, L);
        return -1;
    }
    if (d->frames < 0) {
        /* until the end of the road: the vehicle must get there */
        double x, v, a, tl = d->speed.by_time ? d->speed.x[d->speed.n - 1] : 0;
        road_profile_motion(&d->speed, tl, &x, &v, &a);
        if (v <= 0 && d->start + x < L)
            return road_error_at(d, d->speed.line, err, errlen,
                                 "the vehicle stops before the end of the road; give 'frames' or 'duration'");
    }
    rigctx rc = {g, {d, {{0}, {0}, {0}}, 2 * M_PI * d->body_freq, d->body_damping, d->accel_pitch * DEG}, {0}};
    rough_init(&rc.b.r, d->roughness, d->seed);
    rig_in_body(d, rc.Rbr);
    double y[4] = {0, 0, 0, 0};
    body_input(&rc.b, 0, &y[0], &y[2]);
    long k;
    for (k = 0; d->frames < 0 || k < d->frames; k++) {
        double t = k / d->fps, x, v, a;
        road_profile_motion(&d->speed, t, &x, &v, &a);
        double s = d->start + x;
        /* the length is a sum of quadratures: allow its rounding */
        if (s > L && s <= L * (1 + 1e-12))
            s = L;
        if (s > L) {
            if (d->frames < 0)
                break;
            return road_error_at(d, d->line_frames, err, errlen,
                                 "the vehicle passes the end of the road (%.3f m) at frame %ld (t = %.6g s); give "
                                 "fewer frames, a lower speed or a longer road",
                                 L, k, t);
        }
        if (k > 0)
            body_step(&rc.b, (k - 1) / d->fps, t, y);
        road_frame f;
        road_frame_at_s(g, s, &f);
        road_pose p;
        p.frame = k;
        p.time = t;
        p.s = s;
        p.pitch = y[0];
        p.heave = y[2];
        rig_pose(&rc, &f, y[0], y[2], p.R, p.T);
        if (fn && fn(ctx, &p))
            return -1;
        if (k + 1 >= ROAD_MAX_FRAMES) { /* road_check_limits reports it first */
            k++;
            break;
        }
    }
    return k;
}

/* Shepperd's method: the largest of w, x, y, z is computed from the trace
   combination that cannot cancel, the others from off-diagonal sums. */
void road_quat_from_R(const double R[9], double q[4])
{
    double m00 = R[0], m11 = R[4], m22 = R[8], tr = m00 + m11 + m22;
    double x, y, z, w;
    if (tr >= m00 && tr >= m11 && tr >= m22) {
        double s = 2 * sqrt(1 + tr);
        w = 0.25 * s;
        x = (R[7] - R[5]) / s;
        y = (R[2] - R[6]) / s;
        z = (R[3] - R[1]) / s;
    } else if (m00 >= m11 && m00 >= m22) {
        double s = 2 * sqrt(1 + m00 - m11 - m22);
        x = 0.25 * s;
        w = (R[7] - R[5]) / s;
        y = (R[1] + R[3]) / s;
        z = (R[2] + R[6]) / s;
    } else if (m11 >= m22) {
        double s = 2 * sqrt(1 + m11 - m00 - m22);
        y = 0.25 * s;
        w = (R[2] - R[6]) / s;
        x = (R[1] + R[3]) / s;
        z = (R[5] + R[7]) / s;
    } else {
        double s = 2 * sqrt(1 + m22 - m00 - m11);
        z = 0.25 * s;
        w = (R[3] - R[1]) / s;
        x = (R[2] + R[6]) / s;
        y = (R[5] + R[7]) / s;
    }
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (w < 0)
        n = -n;
    q[0] = x / n;
    q[1] = y / n;
    q[2] = z / n;
    q[3] = w / n;
}

/* ---- other vehicles ----------------------------------------------------- */

int road_vehicle_pose(const road_geo *g, const road_vehicle *v, double time, double M[9], double t[3])
{
    double x, sp, a;
    road_profile_motion(&v->speed, time, &x, &sp, &a);
    double s = v->oncoming ? v->start - x : v->start + x;
    double len = g->c.length;
    /* off the road: on along the tangent of the end it left by, level with
       that end's frame (the road's last or first frame) */
    double sc = s < 0 ? 0 : s > len ? len : s;
    road_frame f;
    road_frame_at_s(g, sc, &f);
    rv3 P = rv_madd(rv_madd(f.C, f.t, s - sc), f.l, v->lateral);
    if (v->oncoming)
        rm_cols(rv_mul(f.l, -1), f.n, rv_mul(f.t, -1), M);
    else
        rm_cols(f.l, f.n, f.t, M);
    t[0] = P.x, t[1] = P.y, t[2] = P.z;
    return s == sc;
}

/* ---- outputs ------------------------------------------------------------ */

typedef struct {
    const road_geo *g;
    FILE *traj, *kitti, *tum, *veh;
    FILE **motion;    /* one per vehicle                                 */
    double R0[9];     /* first frame's rotation and centre, for KITTI's */
    rv3 c0;           /* poses relative to it                            */
    double q_prev[4]; /* the last TUM quaternion, for continuity         */
} outctx;

static int write_pose(void *vctx, const road_pose *p)
{
    outctx *o = vctx;
    const road_desc *d = o->g->d;
    fprintf(o->traj, "%ld ", p->frame);
    road_num(o->traj, p->time);
    fputc(' ', o->traj);
    road_nums(o->traj, p->R, 9, " ");
    fputc(' ', o->traj);
    road_nums(o->traj, p->T, 3, " ");
    fputc('\n', o->traj);
    /* camera-to-world: Rw = R^T, position c = -R^T T */
    double Rw[9];
    rm_transpose(p->R, Rw);
    rv3 c = rm_apply(Rw, rv(-p->T[0], -p->T[1], -p->T[2]));
    /* KITTI: [R|t] of frame i in frame 0's camera: T_c0_w * T_w_ci =
       [R0 Rw_i | R0 (c_i - c_0)].  Frame 0 relative to itself is the
       identity by definition: written as such, not as R0 R0^T (which is
       the identity only to rounding). */
    double row[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    if (p->frame == 0) {
        memcpy(o->R0, p->R, sizeof o->R0);
        o->c0 = c;
    } else {
        double K[9];
        rm_mul(o->R0, Rw, K);
        rv3 kt = rm_apply(o->R0, rv_sub(c, o->c0));
        double r[12] = {K[0], K[1], K[2], kt.x, K[3], K[4], K[5], kt.y, K[6], K[7], K[8], kt.z};
        memcpy(row, r, sizeof row);
    }
    road_nums(o->kitti, row, 12, " ");
    fputc('\n', o->kitti);
    /* TUM: q and -q are the same rotation; frame 0 takes w >= 0, every
       later frame the sign nearer the previous quaternion, so the sequence
       is continuous (interpolating it never takes the long way round) */
    double q[4];
    road_quat_from_R(Rw, q);
    if (p->frame > 0 && q[0] * o->q_prev[0] + q[1] * o->q_prev[1] + q[2] * o->q_prev[2] + q[3] * o->q_prev[3] < 0)
        for (int i = 0; i < 4; i++)
            q[i] = -q[i];
    memcpy(o->q_prev, q, sizeof q);
    double tum[8] = {p->time, c.x, c.y, c.z, q[0], q[1], q[2], q[3]};
    road_nums(o->tum, tum, 8, " ");
    fputc('\n', o->tum);
    /* other vehicles at this time: vehicles.txt while on the road, their
       motion files every frame */
    for (int i = 0; i < d->nveh; i++) {
        double M[9], t3[3];
        int on_road = road_vehicle_pose(o->g, &d->veh[i], p->time, M, t3);
        FILE *out[2] = {on_road ? o->veh : NULL, o->motion[i]};
        for (int k = 0; k < 2; k++) {
            if (!out[k])
                continue;
            fprintf(out[k], "%ld ", p->frame);
            road_num(out[k], p->time);
            if (k == 0)
                fprintf(out[k], " %s", d->veh[i].name);
            fputc(' ', out[k]);
            road_nums(out[k], M, 9, " ");
            fputc(' ', out[k]);
            road_nums(out[k], t3, 3, " ");
            fputc('\n', out[k]);
        }
    }
    for (int i = 0; i < d->nveh; i++)
        if (ferror(o->motion[i]))
            return -1;
    return ferror(o->traj) || ferror(o->kitti) || ferror(o->tum) || ferror(o->veh) ? -1 : 0;
}

int road_emit_motion(const road_geo *g, road_buf *traj, road_buf *kitti, road_buf *tum, road_buf *veh,
                     road_buf *motion, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    int nf = 4 + d->nveh;
    road_buf **b = calloc((size_t)nf, sizeof *b);
    FILE **f = calloc((size_t)nf, sizeof *f);
    int ok = b && f;
    for (int i = 0; ok && i < nf; i++) {
        b[i] = i == 0 ? traj : i == 1 ? kitti : i == 2 ? tum : i == 3 ? veh : &motion[i - 4];
        memset(b[i], 0, sizeof *b[i]);
        f[i] = open_memstream(&b[i]->text, &b[i]->len);
        ok &= f[i] != NULL;
    }
    outctx o = {g, ok ? f[0] : NULL, ok ? f[1] : NULL, ok ? f[2] : NULL, ok ? f[3] : NULL, ok ? f + 4 : NULL,
                {0}, {0, 0, 0}, {0}};
    long n = -1;
    if (ok) {
        fprintf(f[0], "# glsroad trajectory 1\n"
                      "# from %s, %g frames per second\n"
                      "# frame time R(9, row-major) T(3): the rig's pose, P_rig = R * P_world + T\n"
                      "# (spec/road.md).  World frame: x left, y up, z forward; metres, seconds.\n",
                d->file, d->fps);
        fprintf(f[2], "# glsroad: rig poses, camera-to-world in the world frame (x left, y up, z forward)\n"
                      "# timestamp tx ty tz qx qy qz qw\n");
        fprintf(f[3], "# glsroad vehicles 1\n"
                      "# frame time name R(9, row-major) t(3): object-to-world, P_world = R * P_object + t;\n"
                      "# object frame x left, y up, z forward, origin on the road under the vehicle's centre.\n"
                      "# A vehicle off the road at a frame has no line for it.\n");
        for (int i = 0; i < d->nveh; i++)
            fprintf(f[3], "# vehicle %s object %s\n", d->veh[i].name,
                    d->veh[i].object[0] ? d->veh[i].object : "roadobj.Car");
        for (int i = 0; i < d->nveh; i++)
            fprintf(f[4 + i], "# glsroad motion 1\n"
                              "# vehicle %s (object %s) from %s, %g frames per second\n"
                              "# frame time R(9, row-major) T(3): object-to-parent, P_parent = R * P_object + T;\n"
                              "# road.scene calls it with no transform, so its parent frame is the world's.\n"
                              "# Off the road it goes on along the tangent of the end it left by.\n",
                    d->veh[i].name, d->veh[i].object[0] ? d->veh[i].object : "roadobj.Car", d->file, d->fps);
        n = road_run_trajectory(g, write_pose, &o, err, errlen);
    }
    for (int i = 0; f && i < nf; i++)
        if (f[i] && fclose(f[i]) != 0)
            ok = 0;
    if (n < 0 || !ok) {
        if (ok && n < 0) {
            /* err already says why */
        } else
            snprintf(err, errlen, "%s: error: out of memory", d->file);
        for (int i = 0; b && i < nf; i++)
            if (b[i]) {
                free(b[i]->text);
                b[i]->text = NULL;
            }
        free(b);
        free(f);
        return -1;
    }
    free(b);
    free(f);
    return 0;
}
