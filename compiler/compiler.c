/* The compiler's lifetime (new, free, error count) and a small array helper
 * the linker's files share. */
#include <stdlib.h>
#include "buf.h"
#include "linker.h"

gls_compiler *gls_compiler_new(FILE *diag_out)
{
    gls_compiler *c = calloc(1, sizeof *c);
    if (c) {
        c->diag.out = diag_out;
        c->diag.dedupe = 1;
    }
    return c;
}

unsigned gls_compiler_errors(const gls_compiler *c) { return c->diag.errors; }

void gls_compiler_set_build_dir(gls_compiler *c, const char *dir)
{
    if (c)
        c->build_dir = dir;
}

void gls_compiler_free(gls_compiler *c)
{
    if (!c)
        return;
    for (size_t i = 0; i < c->nroots; i++) {
        free(c->roots[i].path);
        gls_bundle_free(c->roots[i].lib);
    }
    for (size_t i = 0; i < c->nall; i++)
        gls_unit_free(c->all[i]);
    for (size_t i = 0; i < c->nalltex; i++) {
        free(c->alltex[i]->name);
        free(c->alltex[i]->tex.rgba);
        free(c->alltex[i]);
    }
    for (size_t i = 0; i < c->nalltpl; i++)
        gls_tpl_free(c->alltpl[i]);
    for (uint32_t i = 0; i < c->nsources; i++)
        free(c->sources[i]);
    gls_strmap_free(&c->units);
    for (size_t i = 0; i < c->missing.cap; i++)
        free(c->missing.vals[i]); /* the key is the value: one strdup each */
    gls_strmap_free(&c->missing);
    gls_strmap_free(&c->textures);
    gls_strmap_free(&c->templates);
    gls_diag_free(&c->diag);
    free(c->roots);
    free(c->all);
    free(c->alltex);
    free(c->alltpl);
    free(c->sources);
    free(c->stack);
    free(c);
}

int gls_push_ptr(void ***arr, size_t *n, size_t *cap, void *p)
{
    if (gls_grow(arr, cap, *n + 1, sizeof **arr))
        return -1;
    (*arr)[(*n)++] = p;
    return 0;
}
