/* The depth-first walk over calls from a unit: loads each callee and each
 * texture the first time it is reached, reports call cycles with their
 * whole path and chains of calls deeper than GLS_MAX_CALL_DEPTH. */
#include <stdio.h>
#include "linker.h"

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
    for (uint32_t i = 0; i < u->ntexrefs && !c->diag.stopped; i++)
        gls_get_texture(c, u->texrefs[i].name, u->texrefs[i].loc);
    for (uint32_t i = 0; i < u->nrefs && !c->diag.stopped; i++) {
        gls_unit *callee = gls_get_unit(c, u->refs[i].name, u->refs[i].loc);
        if (!callee)
            continue;
        if (callee->state == 1) {
            /* the cycle is the part of the stack from callee to u, then callee */
            char path[2048];
            size_t k = 0, start = 0;
            while (start < c->depth && c->stack[start] != callee)
                start++;
            for (size_t j = start; j < c->depth && k < sizeof path; j++)
                k += (size_t)snprintf(path + k, sizeof path - k, "%s -> ", c->stack[j]->name);
            if (k < sizeof path)
                snprintf(path + k, sizeof path - k, "%s", callee->name);
            gls_error_at(&c->diag, u->refs[i].loc, "call cycle: %s", path);
            continue;
        }
        if (callee->state == 0) {
            /* c->depth units are on the stack: calling one more makes a
               chain of c->depth calls; the C stack stays bounded */
            if (c->depth > GLS_MAX_CALL_DEPTH) {
                gls_error_at(&c->diag, u->refs[i].loc, "calls nest more than %u deep", GLS_MAX_CALL_DEPTH);
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
                gls_error_at(&c->diag, u->refs[i].loc, "calls nest more than %u deep", GLS_MAX_CALL_DEPTH);
        }
    }
    c->depth--;
    u->state = 2;
}
