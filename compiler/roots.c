/* Search roots (spec/language.md 1.2): directories and bundle files, the
 * GLSCENE_PATH environment variable, the spelling of root paths, and the
 * file a dotted name stands for under a directory root. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "buf.h"
#include "fileio.h"
#include "linker.h"

/* A copy of path with empty and "." components dropped: "scenelib/",
 * "./scenelib" and "scenelib//" are all "scenelib"; "./" is ".", "//" is
 * "/".  Source paths are recorded in the bundle as the compiler spells them
 * (spec/bundle.md, section 14), so one library spelled differently on the
 * command line still gives the same bytes.  ".." is kept: removing it
 * would be wrong across symbolic links. */
char *gls_normalise_path(const char *path)
{
    size_t n = strlen(path);
    char *out = malloc(n + 2);
    if (!out)
        return NULL;
    size_t k = 0;
    if (path[0] == '/')
        out[k++] = '/';
    for (const char *p = path; *p;) {
        while (*p == '/')
            p++;
        const char *e = p;
        while (*e && *e != '/')
            e++;
        size_t len = (size_t)(e - p);
        if (len && !(len == 1 && p[0] == '.')) {
            if (k && out[k - 1] != '/')
                out[k++] = '/';
            memcpy(out + k, p, len);
            k += len;
        }
        p = e;
    }
    if (k == 0 && n)
        out[k++] = '.';
    out[k] = 0;
    return out;
}

int gls_compiler_add_root(gls_compiler *c, const char *path)
{
    gls_root r = {gls_normalise_path(path), NULL};
    if (!r.path)
        return -1;
    path = r.path;
    if (!gls_is_dir(path)) {
        /* only a missing path is "no such": for a FIFO or a device the
           bundle reader says what it is (and does not block on it) */
        if (access(path, F_OK) != 0) {
            gls_error_at(&c->diag, GLS_NOLOC, "search root %s: no such directory or bundle", path);
            free(r.path);
            return -1;
        }
        gls_error err;
        r.lib = gls_bundle_read_file(path, &err);
        if (!r.lib) {
            gls_error_at(&c->diag, GLS_NOLOC, "search root %s", err.msg);
            free(r.path);
            return -1;
        }
    }
    if (gls_grow(&c->roots, &c->rootscap, c->nroots + 1, sizeof *c->roots)) {
        free(r.path);
        gls_bundle_free(r.lib);
        return -1;
    }
    c->roots[c->nroots++] = r;
    return 0;
}

int gls_compiler_add_env_roots(gls_compiler *c)
{
    const char *env = getenv("GLSCENE_PATH");
    if (!env || !*env)
        return 0;
    char *copy = strdup(env), *save = NULL;
    int rc = 0;
    if (!copy)
        return -1;
    /* a stale entry in the environment is common and harmless: warn, skip */
    for (char *tok = strtok_r(copy, ":", &save); tok; tok = strtok_r(NULL, ":", &save)) {
        if (!*tok)
            continue;
        if (!gls_is_dir(tok) && !gls_is_file(tok)) {
            fprintf(c->diag.out, "glsc: warning: GLSCENE_PATH entry %s does not exist; ignored\n", tok);
            continue;
        }
        if (gls_compiler_add_root(c, tok))
            rc = -1;
    }
    free(copy);
    return rc;
}

/* "a.b.C" + root + ext -> "root/a/b/C.ext" */
char *gls_name_to_path(const char *root, const char *name, const char *ext)
{
    size_t n = strlen(root) + strlen(name) + strlen(ext) + 3;
    char *p = malloc(n);
    if (!p)
        return NULL;
    /* a root of "." adds no prefix, so messages say road/x.scene, not ./road/x.scene */
    int here = strcmp(root, ".") == 0;
    snprintf(p, n, "%s%s%s%s", here ? "" : root, here ? "" : "/", name, ext);
    char *q = p + (here ? 0 : strlen(root) + 1);
    for (size_t i = 0; i < strlen(name); i++)
        if (q[i] == '.')
            q[i] = '/';
    return p;
}

void gls_list_roots(const gls_compiler *c, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = 0;
    for (size_t i = 0; i < c->nroots && k + 1 < n; i++)
        k += (size_t)snprintf(buf + k, n - k, "%s%s", i ? ", " : "", c->roots[i].path);
}

void gls_default_root(gls_compiler *c)
{
    if (c->nroots == 0)
        gls_compiler_add_root(c, ".");
}

int gls_add_root_first(gls_compiler *c, const char *dir)
{
    gls_root r = {gls_normalise_path(dir), NULL};
    if (!r.path || gls_grow(&c->roots, &c->rootscap, c->nroots + 1, sizeof *c->roots)) {
        free(r.path);
        return -1;
    }
    memmove(c->roots + 1, c->roots, c->nroots * sizeof *c->roots);
    c->roots[0] = r;
    c->nroots++;
    return 0;
}
