/* The syntax tree's arena and constructors (ast.h). */
#include <stdalign.h>
#include <stdlib.h>
#include <string.h>
#include "ast.h"

#define CHUNK_BYTES ((size_t)64 << 10)

struct gls_chunk {
    gls_chunk *prev;
    size_t used, cap;
    alignas(max_align_t) unsigned char data[];
};

void *gls_arena_alloc(gls_arena *a, size_t n)
{
    const size_t align = alignof(max_align_t);
    n = (n + align - 1) / align * align;
    gls_chunk *c = a->cur;
    if (!c || c->cap - c->used < n) {
        size_t cap = n > CHUNK_BYTES ? n : CHUNK_BYTES;
        gls_chunk *nc = malloc(sizeof *nc + cap);
        if (!nc)
            return NULL;
        nc->prev = c;
        nc->used = 0;
        nc->cap = cap;
        a->cur = c = nc;
    }
    void *p = c->data + c->used;
    c->used += n;
    memset(p, 0, n);
    return p;
}

gls_arena_mark gls_arena_get_mark(const gls_arena *a)
{
    gls_arena_mark m = {a->cur, a->cur ? a->cur->used : 0};
    return m;
}

void gls_arena_release(gls_arena *a, gls_arena_mark m)
{
    while (a->cur && a->cur != m.chunk) {
        gls_chunk *p = a->cur->prev;
        free(a->cur);
        a->cur = p;
    }
    if (a->cur)
        a->cur->used = m.used;
}

void gls_arena_free(gls_arena *a)
{
    gls_arena_release(a, (gls_arena_mark){NULL, 0});
}

gls_expr *gls_ast_expr(gls_arena *a, gls_expr_kind kind, gls_tok tok)
{
    gls_expr *e = gls_arena_alloc(a, sizeof *e);
    if (e) {
        e->kind = kind;
        e->tok = tok;
    }
    return e;
}

gls_stmt *gls_ast_stmt(gls_arena *a, gls_stmt_kind kind, gls_tok name)
{
    gls_stmt *s = gls_arena_alloc(a, sizeof *s);
    if (s) {
        s->kind = kind;
        s->name = name;
    }
    return s;
}

void gls_elist_add(gls_elist *l, gls_expr *e)
{
    if (!e)
        return;
    if (l->tail)
        l->tail->next = e;
    else
        l->head = e;
    l->tail = e;
    l->n++;
}

void gls_stmt_add(gls_stmt *parent, gls_stmt *s)
{
    if (parent->body_tail)
        parent->body_tail->next = s;
    else
        parent->body = s;
    parent->body_tail = s;
}
