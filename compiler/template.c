/* Parameterised objects (spec/language.md 5.4, spec/bundle.md 7.7).
 *
 * A name stands for a .scene file or a bundle root's entry (gls_tpl).  The
 * file is compiled with its parameters' defaults when it is first found:
 * that object has the plain name, and every parameterised object must
 * compile with its defaults.  A call with other values makes the object
 * for them, once per set of values, named by them ("road.Dash(length=3,
 * width=0.15)", format/specname.h), by running the file's kept tree again
 * with those values.  From a bundle root, an object already there for the
 * values is imported; otherwise the template's source text, kept in the
 * bundle, is parsed and run the same way, so a library bundle stands for
 * its directory also for new values. */
#include <stdlib.h>
#include <string.h>
#include "fileio.h"
#include "linker.h"
#include "specname.h"

static int register_tpl(gls_compiler *c, gls_tpl *t)
{
    if (gls_push_ptr((void ***)&c->alltpl, &c->nalltpl, &c->alltplcap, t) ||
        gls_strmap_put(&c->templates, t->name, t)) {
        gls_tpl_free(t);
        return -1;
    }
    return 0;
}

void gls_tpl_free(gls_tpl *t)
{
    if (!t)
        return;
    for (unsigned i = 0; i < t->nparams; i++)
        free(t->pnames[i]);
    if (t->have_tree)
        gls_tree_free(&t->tree);
    free(t->name);
    free(t);
}

static gls_tpl *new_tpl(gls_compiler *c, const char *name, gls_loc loc)
{
    gls_tpl *t = calloc(1, sizeof *t);
    if (!t || !(t->name = strdup(name))) {
        free(t);
        gls_error_at(&c->diag, loc, "out of memory");
        return NULL;
    }
    t->lib_template = GLS_NONE;
    return t;
}

gls_tpl *gls_tpl_from_file(gls_compiler *c, const char *name, const char *path, gls_loc loc)
{
    char why[512];
    size_t len, mapped;
    char *text = gls_load_source(path, GLS_MAX_INPUT_BYTES, &len, &mapped, why, sizeof why);
    if (!text) {
        gls_error_at(&c->diag, loc, "%s", why);
        return NULL;
    }
    gls_tpl *t = new_tpl(c, name, loc);
    gls_unit *u = calloc(1, sizeof *u);
    uint32_t sf = gls_add_source(c, path);
    if (!t || !u || !(u->name = strdup(name)) || sf == GLS_NONE) {
        gls_release_file(text, mapped);
        gls_unit_free(u);
        gls_tpl_free(t);
        gls_error_at(&c->diag, loc, "out of memory");
        return NULL;
    }
    u->src = (gls_source){c->sources[sf], text, len, mapped};
    u->src_file = sf;
    u->is_top = c->top_name && strcmp(name, c->top_name) == 0;
    u->tpl = t;
    gls_compile_source_keep(u, &c->diag, &t->tree, &c->unrolled);
    t->base = u;
    t->src = u->src;
    t->src_file = sf;
    t->have_tree = t->tree.nparams > 0;
    for (unsigned i = 0; i < t->tree.nparams; i++) {
        gls_tok p = t->tree.pnames[i];
        if (!(t->pnames[i] = strndup(p.p, p.len)))
            break;
        t->defaults[i] = t->tree.defaults[i];
        t->nparams++;
    }
    if (t->nparams != t->tree.nparams)
        gls_error_at(&c->diag, loc, "out of memory");
    if (register_tpl(c, t)) {
        gls_unit_free(u);
        return NULL;
    }
    return gls_register_unit(c, u) == 0 ? t : NULL;
}

gls_tpl *gls_tpl_from_lib(gls_compiler *c, const gls_bundle *b, const char *name, uint32_t oi, uint32_t ti,
                          gls_loc loc)
{
    gls_tpl *t = new_tpl(c, name, loc);
    if (!t)
        return NULL;
    t->lib = b;
    t->lib_template = ti;
    if (ti != GLS_NONE) {
        /* the path first, where compiling the directory would add it */
        const gls_template *bt = &b->templates[ti];
        t->src_file = gls_add_source(c, b->sources[bt->source]);
        if (t->src_file == GLS_NONE) {
            gls_error_at(&c->diag, loc, "out of memory");
            gls_tpl_free(t);
            return NULL;
        }
        t->src = (gls_source){c->sources[t->src_file], bt->text, bt->text_len, 0};
        for (uint32_t k = 0; k < bt->nparams; k++) {
            if (!(t->pnames[k] = strdup(bt->params[k]))) {
                gls_error_at(&c->diag, loc, "out of memory");
                gls_tpl_free(t);
                return NULL;
            }
            t->defaults[k] = bt->defaults[k];
            t->nparams++;
        }
    }
    if (register_tpl(c, t))
        return NULL;
    if (oi != GLS_NONE) {
        gls_unit *u = gls_unit_from_lib(c, b, oi, loc);
        if (!u || gls_register_unit(c, u))
            return NULL;
        u->tpl = t;
        t->base = u;
    }
    return t;
}

int gls_tpl_bind(gls_compiler *c, const gls_tpl *t, const gls_named *args, unsigned nargs, double *values)
{
    int rc = 0;
    memcpy(values, t->defaults, t->nparams * sizeof *values);
    for (unsigned i = 0; i < nargs; i++) {
        unsigned k = 0;
        while (k < t->nparams && strcmp(t->pnames[k], args[i].name) != 0)
            k++;
        if (k < t->nparams) {
            values[k] = args[i].value;
            continue;
        }
        const char *n = args[i].name;
        const char *s = gls_suggest(n, strlen(n), (const char *const *)t->pnames, t->nparams);
        gls_buf list = {0};
        for (unsigned j = 0; j < t->nparams; j++)
            if (gls_buf_put(&list, j ? ", " : "", j ? 2 : 0) || gls_buf_put(&list, t->pnames[j], strlen(t->pnames[j])))
                break;
        if (!t->nparams)
            gls_error_at(&c->diag, args[i].loc, "unknown parameter '%s': '%s' has no parameters", n, t->name);
        else if (s)
            gls_error_at(&c->diag, args[i].loc, "unknown parameter '%s' of '%s'; did you mean '%s'?", n, t->name, s);
        else
            gls_error_at(&c->diag, args[i].loc, "unknown parameter '%s' of '%s' (its parameters: %.*s)", n, t->name,
                         (int)list.len, list.data ? (const char *)list.data : "");
        free(list.data);
        rc = -1;
    }
    return rc;
}

int gls_tpl_object_name(gls_compiler *c, const gls_tpl *t, const double *values, gls_buf *b, gls_loc loc)
{
    int defaults = memcmp(values, t->defaults, t->nparams * sizeof *values) == 0;
    b->len = 0;
    if (gls_specname_write(b, t->name, (const char *const *)t->pnames, values, defaults ? 0 : t->nparams)) {
        gls_error_at(&c->diag, loc, "out of memory");
        return -1;
    }
    if (b->len > GLS_MAX_NAME_BYTES) {
        gls_error_at(&c->diag, loc, "the name of the object for these values, %.60s..., is longer than %u bytes",
                     (const char *)b->data, GLS_MAX_NAME_BYTES);
        return -1;
    }
    return 0;
}

/* Does the text of a bundle's template declare the parameters and defaults
 * its table lists?  A bundle made by glsc always does; a damaged or
 * hostile one may not, and its objects would then be named for values it
 * does not use. */
static int tree_matches(const gls_tpl *t)
{
    if (t->tree.nparams != t->nparams)
        return 0;
    for (unsigned k = 0; k < t->nparams; k++) {
        gls_tok p = t->tree.pnames[k];
        if (p.len != strlen(t->pnames[k]) || memcmp(p.p, t->pnames[k], p.len) != 0 ||
            memcmp(&t->tree.defaults[k], &t->defaults[k], sizeof(double)) != 0)
            return 0;
    }
    return 1;
}

/* Make t's object for values, named name: import it from t's bundle root
 * when it is there, else run t's tree (parsed from the bundle's text the
 * first time) with the values. */
static gls_unit *make(gls_compiler *c, gls_tpl *t, const double *values, const char *name, gls_loc loc)
{
    uint32_t oi = t->lib ? gls_bundle_find_object(t->lib, name) : GLS_NONE;
    if (oi != GLS_NONE) {
        gls_unit *u = gls_unit_from_lib(c, t->lib, oi, loc);
        if (!u || gls_register_unit(c, u))
            return NULL;
        u->tpl = t;
        return u;
    }
    if (c->nall >= GLS_MAX_OBJECTS) {
        gls_error_at(&c->diag, loc, "the scene has more than %u objects", GLS_MAX_OBJECTS);
        return NULL;
    }
    if (!t->have_tree) {
        if (t->lib_template == GLS_NONE)
            return NULL; /* a plain bundle object: only its defaults */
        int rc = gls_parse_tree(&t->src, &c->diag, &t->tree);
        if (rc || !tree_matches(t)) {
            if (!rc)
                gls_error_at(&c->diag, loc, "the template of '%s' in a search root does not match its source text "
                             "(other parameters or defaults): rebuild that bundle", t->name);
            gls_tree_free(&t->tree);
            t->lib_template = GLS_NONE; /* reported once: no other object is made from it */
            return NULL;
        }
        t->have_tree = 1;
    }
    gls_named binding[GLS_MAX_PARAMS];
    for (unsigned k = 0; k < t->nparams; k++)
        binding[k] = (gls_named){t->pnames[k], values[k], loc};
    gls_unit *u = calloc(1, sizeof *u);
    if (!u || !(u->name = strdup(name))) {
        free(u);
        gls_error_at(&c->diag, loc, "out of memory");
        return NULL;
    }
    u->src = t->src;
    u->src_borrowed = 1;
    u->src_file = t->src_file;
    u->tpl = t;
    const char *making = c->diag.making;
    gls_loc making_at = c->diag.making_at;
    if (loc.src) {
        c->diag.making = u->name;
        c->diag.making_at = loc;
    }
    gls_run_tree(u, &c->diag, &t->tree, binding, t->nparams, &c->unrolled);
    c->diag.making = making;
    c->diag.making_at = making_at;
    return gls_register_unit(c, u) == 0 ? u : NULL;
}

gls_unit *gls_get_unit(gls_compiler *c, const char *name, const gls_named *args, unsigned nargs, gls_loc loc)
{
    gls_tpl *t = gls_get_tpl(c, name, loc);
    double values[GLS_MAX_PARAMS];
    if (!t || gls_tpl_bind(c, t, args, nargs, values))
        return NULL;
    if (!nargs && t->base)
        return t->base;
    gls_buf b = {0};
    gls_unit *u = NULL;
    if (gls_tpl_object_name(c, t, values, &b, loc) == 0) {
        const char *on = (const char *)b.data;
        u = gls_strmap_get(&c->units, on);
        if (!u)
            u = make(c, t, values, on, loc);
    }
    free(b.data);
    return u;
}
