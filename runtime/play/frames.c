/* A run's frames (frames.h). */
#include <string.h>
#include "frames.h"

int gls_frames_open(gls_frames *f, const gls_traj_text *tx, FILE *notes, uint64_t first, uint64_t end,
                    const gls_shard *shard)
{
    memset(f, 0, sizeof *f);
    f->first = first, f->end = end, f->shard = shard;
    f->t = gls_traj_open_text(tx, notes);
    return f->t ? 0 : -1;
}

int gls_frames_next(gls_frames *f, gls_traj_pose *p, gls_frame_mark *m, char *err, size_t errlen)
{
    int got;
    if (f->past)
        return 0;
    while ((got = gls_traj_next(f->t, p, err, errlen)) == 1) {
        if (p->frame < f->first)
            continue;
        if (p->frame >= f->end) {
            f->past = 1, f->after = *p;
            return 0;
        }
        m->mine = gls_shard_has(f->shard, f->first, p->frame);
        m->complete = m->mine && f->complete && f->complete(f->ud, p->frame);
        return 1;
    }
    return got;
}

int gls_frames_rest(gls_frames *f, char *err, size_t errlen)
{
    gls_traj_pose p;
    gls_frame_mark m;
    int got;
    while ((got = gls_frames_next(f, &p, &m, err, errlen)) == 1)
        ;
    if (got < 0)
        return -1;
    while ((got = gls_traj_next(f->t, &p, err, errlen)) == 1)
        ;
    return got < 0 ? -1 : 0;
}

void gls_frames_close(gls_frames *f)
{
    gls_traj_close(f->t);
    f->t = NULL;
}
