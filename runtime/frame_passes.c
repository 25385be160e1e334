/* The passes of a camera frame (frame_passes.h). */
#include "frame_passes.h"
#include "player.h"

gls_frame_passes gls_frame_passes_of(const gls_camera *c, int moving, const gls_aa_plan *p, unsigned outputs)
{
    gls_frame_passes f;
    int pixels = (outputs & (GLS_OUT_IMAGE | GLS_OUT_EDGE_MAPS)) != 0; /* what the accumulator makes */
    f.ex = gls_exposure_of(c, moving);
    f.fx = gls_exposure_on(&f.ex) && pixels;
    f.aa = (p->count > 1 || f.fx) && pixels;
    f.centre = !f.aa || (outputs & GLS_OUT_FROM_Z);
    return f;
}
