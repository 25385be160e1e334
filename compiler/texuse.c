/* The "texture has no effect" warning (texuse.h). */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "texuse.h"

void gls_texuse_init(gls_texuse *t, int top)
{
    memset(t, 0, sizeof *t);
    t->top = top;
    t->cur.mode = TEXUSE_INHERITED;
    t->cur.sel = -1;
}

int gls_texuse_select(gls_texuse *t, gls_loc loc, const char *name, size_t n)
{
    if (gls_grow(&t->sel, &t->cap, t->nsel + 1, sizeof *t->sel))
        return -1;
    char *copy = strndup(name, n); /* a valid name: no NUL inside */
    if (!copy)
        return -1;
    t->sel[t->nsel] = (gls_texsel){loc, copy, UINT_MAX, 0};
    t->cur.sel = (long)t->nsel++;
    return 0;
}

void gls_texuse_deselect(gls_texuse *t)
{
    t->cur.sel = -1;
}

void gls_texuse_mode(gls_texuse *t, int textured, unsigned line)
{
    t->cur.mode = textured ? TEXUSE_TEXTURED : TEXUSE_COLOR;
    t->cur.color_line = textured ? 0 : line;
}

void gls_texuse_push(gls_texuse *t, unsigned depth)
{
    if (depth < GLS_MAX_PUSH_DEPTH)
        t->saved[depth] = t->cur;
}

void gls_texuse_pop(gls_texuse *t, unsigned depth)
{
    if (depth < GLS_MAX_PUSH_DEPTH)
        t->cur = t->saved[depth];
}

void gls_texuse_call(gls_texuse *t)
{
    if (t->cur.sel >= 0)
        t->sel[t->cur.sel].used = 1;
}

void gls_texuse_draw(gls_texuse *t)
{
    if (t->cur.sel < 0)
        return;
    gls_texsel *s = &t->sel[t->cur.sel];
    int color = t->cur.mode == TEXUSE_COLOR || (t->cur.mode == TEXUSE_INHERITED && t->top);
    if (!color)
        s->used = 1;
    else if (s->color_line == UINT_MAX)
        s->color_line = t->cur.mode == TEXUSE_COLOR ? t->cur.color_line : 0;
}

void gls_texuse_finish(gls_texuse *t, gls_diag *d)
{
    for (size_t i = 0; i < t->nsel; i++) {
        const gls_texsel *s = &t->sel[i];
        if (!s->used && s->color_line != UINT_MAX) {
            char why[64];
            if (s->color_line)
                snprintf(why, sizeof why, "set by texmode(color) on line %u", s->color_line);
            else
                snprintf(why, sizeof why, "the default");
            gls_warning_at(d, s->loc,
                           "texture '%s' is never applied: the texture mode is color (%s), which draws plain "
                           "colour; write texmode(replace); or texmode(modulate); before drawing",
                           s->name, why);
        }
        free(t->sel[i].name);
    }
    free(t->sel);
    t->sel = NULL;
    t->nsel = t->cap = 0;
}
