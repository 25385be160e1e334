/* The depth-first walk over calls from a unit: finds each callee (made
 * for the call's parameter values) and each texture the first time it is
 * reached, reports call cycles with their whole path and chains of calls
 * deeper than GLS_MAX_CALL_DEPTH.  A cycle is found by name, whatever the
 * parameter values: an object may not call itself, also not with other
 * values (so no chain of specialisations can grow without end). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "linker.h"

/* "call cycle: a.B -> a.C -> a.B", from the first object of callee's name
 * on the path; values that differ from that object's say why this is one. */
static void cycle_error(gls_compiler *c, const gls_tpl *callee, const gls_ref *r)
{
    char path[2048];
    size_t k = 0, start = 0;
    while (start < c->depth && c->stack[start]->tpl != callee)
        start++;
    for (size_t j = start; j < c->depth && k < sizeof path; j++)
        k += (size_t)snprintf(path + k, sizeof path - k, "%s -> ", c->stack[j]->name);
    double values[GLS_MAX_PARAMS];
    gls_buf name = {0};
    int other_values = 0;
    if (gls_tpl_bind(c, callee, r->args, r->nargs, values) == 0 &&
        gls_tpl_object_name(c, callee, values, &name, r->loc) == 0) {
        if (k < sizeof path)
            snprintf(path + k, sizeof path - k, "%s", (const char *)name.data);
        other_values = start < c->depth && strcmp(c->stack[start]->name, (const char *)name.data) != 0;
    }
    free(name.data);
    gls_error_at(&c->diag, r->loc, "call cycle: %s%s", path,
                 other_values ? " (an object cannot call itself, not even with other parameter values)" : "");
}

/* Depth-first walk over calls from u: loads callees and textures, detects
 * cycles.  Recursion depth is bounded by GLS_MAX_CALL_DEPTH. */
void gls_visit(gls_compiler *c, gls_unit *u)
{
    if (u->state)
        return;
    u->state = 1;
    if (gls_push_ptr((void ***)&c->stack, &c->depth, &c->stackcap, u)) {
        gls_error_at(&c->diag, GLS_NOLOC, "out of memory");
        u->state = 2;
        return;
    }
    if (u->tpl)
        u->tpl->on_stack++;
    for (uint32_t i = 0; i < u->ntexrefs && !c->diag.stopped; i++)
        gls_get_texture(c, u->texrefs[i].name, u->texrefs[i].loc);
    for (uint32_t i = 0; i < u->nrefs && !c->diag.stopped; i++) {
        gls_ref *r = &u->refs[i];
        gls_tpl *t = gls_get_tpl(c, r->name, r->loc);
        if (!t)
            continue;
        if (t->on_stack) {
            cycle_error(c, t, r);
            continue;
        }
        gls_unit *callee = gls_get_unit(c, r->name, r->args, r->nargs, r->loc);
        if (!callee)
            continue;
        r->target = callee;
        if (callee->state == 0) {
            /* c->depth units are on the stack: calling one more makes a
               chain of c->depth calls; the C stack stays bounded */
            if (c->depth > GLS_MAX_CALL_DEPTH) {
                gls_error_at(&c->diag, r->loc, "calls nest more than %u deep", GLS_MAX_CALL_DEPTH);
                continue;
            }
            gls_visit(c, callee);
        }
        /* the longest chain through an already visited callee counts too
           (the same rule as the bundle validator: at most
           GLS_MAX_CALL_DEPTH nested calls) */
        if (callee->state == 2 && callee->height + 1 > u->height) {
            u->height = callee->height + 1;
            /* report where the limit is first crossed, not at every caller */
            if (u->height > GLS_MAX_CALL_DEPTH && callee->height <= GLS_MAX_CALL_DEPTH)
                gls_error_at(&c->diag, r->loc, "calls nest more than %u deep", GLS_MAX_CALL_DEPTH);
        }
    }
    if (u->tpl)
        u->tpl->on_stack--;
    c->depth--;
    u->state = 2;
}
