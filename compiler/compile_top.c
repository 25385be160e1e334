/* Top mode (spec/language.md 1.4, 1.5): compile one top-level object, given
 * as a .scene path or a dotted name, and everything it reaches. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "fileio.h"
#include "linker.h"

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

/* The object name of a .scene file: its path below a directory root, or
 * else its file name without .scene. */
static char *name_of_file(gls_compiler *c, const char *path)
{
    char full[PATH_MAX], rootfull[PATH_MAX];
    const char *rel = NULL;
    if (realpath(path, full)) {
        for (size_t i = 0; i < c->nroots && !rel; i++) {
            if (c->roots[i].lib || !realpath(c->roots[i].path, rootfull))
                continue;
            size_t n = strlen(rootfull);
            if (strncmp(full, rootfull, n) == 0 && full[n] == '/')
                rel = full + n + 1;
        }
    }
    if (!rel) {
        rel = strrchr(path, '/');
        rel = rel ? rel + 1 : path;
    }
    char *name = strdup(rel);
    if (!name)
        return NULL;
    name[strlen(name) - strlen(".scene")] = 0;
    for (char *q = name; *q; q++)
        if (*q == '/')
            *q = '.';
    return name;
}

int gls_compile_top(gls_compiler *c, const char *top, gls_bundle **out)
{
    *out = NULL;
    gls_default_root(c);
    gls_unit *u = NULL;
    if (ends_with(top, ".scene")) {
        char *name = name_of_file(c, top);
        if (!name || !gls_valid_object_name(name)) {
            gls_error_at(&c->diag, GLS_NOLOC,
                         "%s: cannot make an object name from this file name (use letters, digits and '_')", top);
            free(name);
            return -1;
        }
        /* a FIFO or a device is not "no such file": reading says what it is */
        if (!gls_is_file(top)) {
            gls_error_at(&c->diag, GLS_NOLOC, "%s: no such file", top);
            free(name);
            return -1;
        }
        char *spelt = gls_normalise_path(top);
        c->top_name = name;
        gls_tpl *t = spelt ? gls_tpl_from_file(c, name, spelt, GLS_NOLOC) : NULL;
        c->top_name = NULL;
        free(spelt);
        free(name);
        if (!t || !(u = t->base))
            return -1;
    } else {
        if (!gls_valid_object_name(top)) {
            gls_error_at(&c->diag, GLS_NOLOC, "'%s' is neither a .scene file nor a dotted object name", top);
            return -1;
        }
        c->top_name = top;
        u = gls_get_unit(c, top, NULL, 0, GLS_NOLOC);
        c->top_name = NULL;
        if (!u)
            return -1;
    }
    gls_visit(c, u);
    if (c->diag.errors)
        return -1;
    gls_bundle *b = gls_assemble(c, u, 0);
    if (!b)
        return -1;
    if (gls_check_instance_names(c, b)) {
        gls_bundle_free(b);
        return -1;
    }
    /* each call path is an instance to draw: bounded like the player's
     * instance table (the vertices on all paths are not: the player keeps
     * each object's geometry once) */
    uint64_t np = 0;
    if (gls_bundle_count_paths(b, b->top, &np)) {
        gls_error_at(&c->diag, GLS_NOLOC, "out of memory");
        gls_bundle_free(b);
        return -1;
    }
    if (np > GLS_MAX_CALL_PATHS) {
        gls_error_at(&c->diag, GLS_NOLOC,
                     "%s has more than %u call paths (instances to draw) once its calls are unrolled: too many "
                     "to render",
                     u->name, GLS_MAX_CALL_PATHS);
        gls_bundle_free(b);
        return -1;
    }
    gls_error err;
    if (gls_bundle_validate(b, &err)) {
        gls_error_at(&c->diag, GLS_NOLOC, "internal error: built bundle fails validation: %s (format check line %d)",
                     err.msg, err.check_line);
        gls_bundle_free(b);
        return -1;
    }
    *out = b;
    return 0;
}
