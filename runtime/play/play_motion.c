/* The --motion set (play_int.h): the named instances and their motion
 * files loaded against the scene, each frame checked to have its rows
 * (and, for an exposure that spans time, the rows around it), the
 * instances posed for a frame, and the set freed. */
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "play_int.h"
#include "suggest.h"

/* Every camera whose exposure spans more than the frame time (shutter,
 * line_delay) needs poses at each time of the span: within the rows of
 * the trajectory and of every motion (interpolated, never extrapolated,
 * subframe.h).  0, or -1 after a message. */
int play_exposure_check(const motion_set *ms, const gls_camera *cams, const char *const *names, size_t ncams,
                        uint64_t frame, FILE *errs)
{
    for (size_t c = 0; c < ncams; c++) {
        gls_exposure e = gls_exposure_of(&cams[c], ms->moving);
        if (!e.blur && !e.rolling)
            continue;
        double s0, s1;
        gls_exposure_span(&cams[c], &e, &s0, &s1);
        double x0 = (double)frame + s0, x1 = (double)frame + s1;
        for (size_t i = 0; i <= ms->n; i++) {
            const gls_motion *m = i < ms->n ? &ms->m[i] : &ms->rig;
            if (!m->n || (x0 >= (double)m->frame[0] && x1 <= (double)m->frame[m->n - 1]))
                continue;
            char a[40], b[40];
            gls_fmt_double(a, sizeof a, x0);
            gls_fmt_double(b, sizeof b, x1);
            fprintf(errs, "glsplay: error: camera %s, frame %llu: its exposure spans frames %s to %s, beyond the rows "
                          "of %s (frames %llu to %llu); sub-frame poses are interpolated between rows, never "
                          "extrapolated: render fewer --frames or extend the file\n",
                    names[c], (unsigned long long)frame, a, b, m->path, (unsigned long long)m->frame[0],
                    (unsigned long long)m->frame[m->n - 1]);
            return -1;
        }
    }
    return 0;
}

/* Every frame to be rendered must have a row in every motion file. */
int play_motion_check(const motion_set *ms, uint64_t frame, FILE *errs)
{
    double R[9], T[3];
    for (size_t i = 0; i < ms->n; i++)
        if (gls_motion_pose(&ms->m[i], frame, R, T)) {
            fprintf(errs, "glsplay: error: %s: no row for frame %llu (the motion of instance %s)\n", ms->m[i].path,
                    (unsigned long long)frame, ms->scene->inst[ms->inst[i]].name);
            return -1;
        }
    return 0;
}

/* Pose the moving instances for frame (checked by play_motion_check). */
void play_motion_apply(const motion_set *ms, uint64_t frame)
{
    double R[9], T[3];
    for (size_t i = 0; i < ms->n; i++)
        if (gls_motion_pose(&ms->m[i], frame, R, T) == 0)
            gls_scene_move(ms->scene, ms->inst[i], R, T);
    if (ms->n)
        gls_scene_update(ms->scene);
}

/* Read the --motion arguments against the scene's instance names.  0, or
 * 1 after a message. */
int play_motion_load(const gls_play_opts *o, motion_set *ms, FILE *errs)
{
    char err[1024];
    ms->inst = calloc(o->nmotions ? o->nmotions : 1, sizeof *ms->inst);
    ms->m = calloc(o->nmotions ? o->nmotions : 1, sizeof *ms->m);
    if (!ms->inst || !ms->m) {
        fprintf(errs, "glsplay: error: out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < o->nmotions; i++) {
        const char *arg = o->motions[i], *eq = strchr(arg, '=');
        char name[GLS_INSTANCE_NAME_MAX + 2];
        size_t len = (size_t)(eq - arg);
        snprintf(name, sizeof name, "%.*s", (int)(len < sizeof name - 1 ? len : sizeof name - 1), arg);
        uint32_t k = len <= GLS_INSTANCE_NAME_MAX ? gls_scene_find_instance(ms->scene, name) : GLS_NONE;
        if (k == GLS_NONE) {
            const char **names = calloc(ms->scene->ninst ? ms->scene->ninst : 1, sizeof *names);
            size_t nn = 0;
            for (uint32_t j = 0; names && j < ms->scene->ninst; j++)
                if (ms->scene->inst[j].name)
                    names[nn++] = ms->scene->inst[j].name;
            const char *s = names ? gls_suggest(arg, len, names, nn) : NULL;
            fprintf(errs, "glsplay: error: --motion %.*s: %s has no instance named '%.*s'%s%s%s\n", (int)len, arg,
                    o->bundle, (int)len, arg, s ? "; did you mean '" : nn ? "" : " (it names no instance)",
                    s ? s : "", s ? "'?" : "");
            free(names);
            return 1;
        }
        for (size_t j = 0; j < i; j++)
            if (ms->inst[j] == k) {
                fprintf(errs, "glsplay: error: --motion %s: instance %s is moved twice\n", arg, name);
                return 1;
            }
        ms->inst[i] = k;
        int got = gls_motion_read(eq + 1, errs, &ms->m[i], err, sizeof err);
        if (got) {
            /* the file itself (missing, a FIFO...): say which option named it */
            if (got == -2)
                fprintf(errs, "glsplay: error: --motion %s: %s\n", arg, err);
            else
                fprintf(errs, "%s\n", err);
            return 1;
        }
        ms->n = i + 1;
    }
    return 0;
}

void play_motion_free(motion_set *ms)
{
    for (size_t i = 0; ms->m && i < ms->n; i++)
        gls_motion_free(&ms->m[i]);
    gls_motion_free(&ms->rig);
    gls_traj_text_free(&ms->traj);
    free(ms->m);
    free(ms->inst);
}
