/* Instance names in a scene (spec/language.md 7): each names one drawn
 * instance, so a name is given by one call of the whole scene, and that
 * call is reached once from the top object.  Checked on the assembled
 * bundle, where the number of call paths to each object is known, with
 * the errors at the calls that give the names. */
#include <stdlib.h>
#include "linker.h"

int gls_check_instance_names(gls_compiler *c, const gls_bundle *b)
{
    if (!b->ninstnames || b->top == GLS_NONE)
        return 0;
    uint64_t *paths = gls_bundle_paths(b, b->top);
    const gls_unit **by_index = calloc(b->nobjects, sizeof *by_index);
    gls_strmap first = {0}; /* name -> the gls_ref that gives it first */
    int ret = -1;
    if (!paths || !by_index) {
        gls_error_at(&c->diag, GLS_NOLOC, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < c->nall; i++)
        if (c->all[i]->state == 2 && c->all[i]->final_index < b->nobjects)
            by_index[c->all[i]->final_index] = c->all[i];
    /* in bundle order (objects sorted by name), so errors come in an order
       that does not depend on the order objects were found in */
    for (uint32_t oi = 0; oi < b->nobjects; oi++) {
        const gls_unit *u = by_index[oi];
        for (uint32_t j = 0; u && j < u->ninstnames; j++) {
            const gls_ref *r = &u->instnames[j];
            const gls_ref *was = gls_strmap_get(&first, r->name);
            if (was) {
                gls_error_at(&c->diag, r->loc, "instance name \"%s\" is given twice in the scene", r->name);
                gls_note_at(&c->diag, was->loc, "\"%s\" is first given here", r->name);
            } else if (gls_strmap_put(&first, r->name, (void *)r)) {
                gls_error_at(&c->diag, GLS_NOLOC, "out of memory");
                goto done;
            }
            if (paths[oi] > 1)
                gls_error_at(&c->diag, r->loc,
                             "instance name \"%s\" is on a call reached %llu times through the call tree (%s is "
                             "drawn %llu times): a name must name one drawn instance",
                             r->name, (unsigned long long)paths[oi], u->name, (unsigned long long)paths[oi]);
        }
    }
    ret = c->diag.errors ? -1 : 0;
done:
    gls_strmap_free(&first);
    free(paths);
    free(by_index);
    return ret;
}
