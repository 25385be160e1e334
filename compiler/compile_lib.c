/* Library mode (spec/language.md 1.5): every object and texture under a
 * directory, scanned with names sorted, into a bundle with no top. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fileio.h"
#include "linker.h"

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Collect the names of every .scene file and texture under dir. */
static int scan_dir(gls_compiler *c, const char *dir, const char *prefix, int depth)
{
    if (depth > 64) {
        gls_error_at(&c->diag, GLS_NOLOC, "%s: directories nested too deeply", dir);
        return -1;
    }
    DIR *d = opendir(dir);
    if (!d) {
        gls_error_at(&c->diag, GLS_NOLOC, "cannot read directory %s", dir);
        return -1;
    }
    /* read all names, then sort: the result must not depend on readdir order */
    char **names = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        char *s = strdup(e->d_name);
        if (!s || gls_push_ptr((void ***)&names, &n, &cap, s)) {
            free(s);
            break;
        }
    }
    closedir(d);
    qsort(names, n, sizeof *names, cmp_str);
    int rc = 0;
    for (size_t i = 0; i < n; i++) {
        size_t plen = strlen(dir) + strlen(names[i]) + 2;
        char *path = malloc(plen);
        char *qual = malloc(strlen(prefix) + strlen(names[i]) + 2);
        if (!path || !qual) {
            free(path);
            free(qual);
            rc = -1;
            break;
        }
        snprintf(path, plen, "%s/%s", dir, names[i]);
        sprintf(qual, "%s%s%s", prefix, *prefix ? "." : "", names[i]);
        if (gls_is_dir(path)) {
            if (gls_valid_object_name(qual))
                rc |= scan_dir(c, path, qual, depth + 1);
        } else {
            char *dot = strrchr(qual, '.');
            char *base = strrchr(names[i], '.');
            int known = 0;
            for (size_t k = 0; base && k < sizeof gls_tex_exts / sizeof gls_tex_exts[0]; k++)
                known |= strcmp(base, gls_tex_exts[k]) == 0;
            if (base && (known || strcmp(base, ".scene") == 0) && memchr(names[i], '.', (size_t)(base - names[i]))) {
                /* "a.b.scene" would be named a.b and looked up as a/b.scene */
                gls_error_at(&c->diag, GLS_NOLOC, "%s: a file name must be an identifier before its extension", path);
                rc = -1;
            } else if (base && dot) {
                *dot = 0;
                if (strcmp(base, ".scene") == 0 && gls_valid_object_name(qual))
                    gls_get_unit(c, qual, NULL, 0, GLS_NOLOC);
                else
                    for (size_t k = 0; k < sizeof gls_tex_exts / sizeof gls_tex_exts[0]; k++)
                        if (strcmp(base, gls_tex_exts[k]) == 0 && gls_valid_object_name(qual))
                            gls_get_texture(c, qual, GLS_NOLOC);
            }
        }
        free(path);
        free(qual);
    }
    for (size_t i = 0; i < n; i++)
        free(names[i]);
    free(names);
    return rc;
}

int gls_compile_lib(gls_compiler *c, const char *root, gls_bundle **out)
{
    *out = NULL;
    if (!gls_is_dir(root)) {
        gls_error_at(&c->diag, GLS_NOLOC, "--lib %s: not a directory", root);
        return -1;
    }
    /* the library root is searched first, then the other roots */
    if (gls_add_root_first(c, root))
        return -1;
    scan_dir(c, c->roots[0].path, "", 0);
    for (size_t i = 0; i < c->nall && !c->diag.stopped; i++)
        gls_visit(c, c->all[i]);
    if (c->diag.errors)
        return -1;
    gls_bundle *b = gls_assemble(c, NULL, 1);
    if (!b)
        return -1;
    gls_error err;
    if (gls_bundle_validate(b, &err)) {
        gls_error_at(&c->diag, GLS_NOLOC, "internal error: built bundle fails validation: %s", err.msg);
        gls_bundle_free(b);
        return -1;
    }
    *out = b;
    return 0;
}
