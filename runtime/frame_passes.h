/* How a camera frame is drawn, decided in one place for the player
 * (play_camera) and --explain (explain.c), so that the plan printed is
 * the one drawn: whether the image comes from an accumulator (more than
 * one anti-aliasing sample, or an exposure effect's sub-frame renders,
 * exposure.h, even at --aa 1) and whether an unjittered centre pass is
 * drawn (no accumulator, or an output made from depth). */
#ifndef GLS_FRAME_PASSES_H
#define GLS_FRAME_PASSES_H
#include "aa.h"
#include "camera.h"
#include "exposure.h"

typedef struct {
    gls_exposure ex; /* the camera's effects                           */
    int fx;          /* one of them acts on the image or edges map      */
    int aa;          /* the image and edges map come from an accumulator */
    int centre;      /* one unjittered centre pass                      */
} gls_frame_passes;

/* Camera c under the plan p, with outputs (GLS_OUT_* bits) asked for;
 * moving: something moves (--trajectory or --motion), without which
 * shutter and line_delay do nothing. */
gls_frame_passes gls_frame_passes_of(const gls_camera *c, int moving, const gls_aa_plan *p, unsigned outputs);

#endif
