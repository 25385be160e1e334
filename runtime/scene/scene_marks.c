/* Landmarks while a bundle is walked into a scene (scene_marks.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "scene_marks.h"

static int path_set(gls_markwalk *m, size_t at, const char *text)
{
    size_t n = strlen(text);
    if (gls_grow(&m->path, &m->pathcap, at + n + 1, 1))
        return -1;
    memcpy(m->path + at, text, n + 1);
    m->len = at + n;
    return 0;
}

int gls_markwalk_init(gls_markwalk *m, const gls_bundle *b)
{
    memset(m, 0, sizeof *m);
    m->b = b;
    m->on = b->nmarknames > 0;
    if (!m->on)
        return 0;
    m->callk = calloc(b->nobjects, sizeof *m->callk);
    m->count = calloc(b->nobjects, sizeof *m->count);
    if (!m->callk || !m->count)
        return -1;
    return path_set(m, 0, b->objects[b->top].name);
}

const uint32_t *gls_markwalk_calls(gls_markwalk *m, uint32_t oi)
{
    if (m->callk[oi])
        return m->callk[oi];
    const gls_object *o = &m->b->objects[oi];
    gls_insn in;
    size_t pos = 0, n = 0;
    while (gls_insn_decode(o->code, o->code_len, &pos, &in) == 0 && in.op != GLS_OP_END)
        n += in.op == GLS_OP_CALL || in.op == GLS_OP_CALLN;
    uint32_t *k = malloc((n ? n : 1) * sizeof *k);
    if (!k)
        return NULL;
    /* k = 1 + the earlier calls of the same object; count[] back to 0 after */
    for (int pass = 0; pass < 2; pass++) {
        size_t j = 0;
        pos = 0;
        while (gls_insn_decode(o->code, o->code_len, &pos, &in) == 0 && in.op != GLS_OP_END)
            if (in.op == GLS_OP_CALL || in.op == GLS_OP_CALLN) {
                uint32_t callee = in.u[GLS_ARG_CALL_OBJECT];
                if (pass == 0)
                    k[j++] = ++m->count[callee];
                else
                    m->count[callee] = 0;
            }
    }
    return m->callk[oi] = k;
}

int gls_markwalk_enter(gls_markwalk *m, uint32_t callee, uint32_t k, size_t *saved)
{
    *saved = m->len;
    if (!m->on)
        return 0;
    const char *name = m->b->objects[callee].name;
    char num[16];
    snprintf(num, sizeof num, "#%u", k);
    size_t n = strlen(name), at = m->len;
    if (gls_grow(&m->path, &m->pathcap, at + 3 + n + strlen(num) + 1, 1))
        return -1;
    memcpy(m->path + at, " > ", 3);
    memcpy(m->path + at + 3, name, n);
    return path_set(m, at + 3 + n, num);
}

void gls_markwalk_leave(gls_markwalk *m, size_t saved)
{
    if (m->on) {
        m->len = saved;
        m->path[saved] = 0;
    }
}

int gls_markwalk_place(gls_markwalk *m, uint32_t inst, uint32_t name, const double p[4])
{
    if (m->n >= GLS_SCENE_MAX_MARKS)
        return -2;
    if (gls_grow(&m->marks, &m->cap, m->n + 1, sizeof *m->marks))
        return -1;
    gls_mark *k = &m->marks[m->n];
    k->name = name, k->inst = inst;
    memcpy(k->p, p, sizeof k->p);
    if (!(k->path = strdup(m->path)))
        return -1;
    m->n++;
    return 0;
}

int gls_markwalk_finish(gls_markwalk *m, gls_scene *s)
{
    if (!m->on)
        return 0;
    s->marknames = calloc(m->b->nmarknames, sizeof *s->marknames);
    if (!s->marknames)
        return -1;
    s->nmarknames = m->b->nmarknames;
    for (uint32_t i = 0; i < s->nmarknames; i++)
        if (!(s->marknames[i] = strdup(m->b->marknames[i])))
            return -1;
    s->marks = m->marks, s->nmarks = (uint32_t)m->n;
    m->marks = NULL, m->n = 0;
    return 0;
}

void gls_markwalk_free(gls_markwalk *m)
{
    for (size_t i = 0; i < m->n; i++)
        free(m->marks[i].path);
    free(m->marks);
    for (uint32_t i = 0; m->callk && i < m->b->nobjects; i++)
        free(m->callk[i]);
    free(m->callk);
    free(m->count);
    free(m->path);
    memset(m, 0, sizeof *m);
}
