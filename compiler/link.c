/* The compiler's driver and linker: finds objects and textures through the
 * search roots, compiles each object once, follows calls depth-first
 * (reporting cycles with their whole path), and assembles the reachable
 * units into a bundle with bundle-global, relocated indices. */
#include <dirent.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "compile.h"
#include "fileio.h"
#include "strmap.h"
#include "unit.h"

typedef struct {
    char *path;
    gls_bundle *lib;      /* non-NULL for a bundle root */
} gls_root;

typedef struct {
    char *name;
    gls_texture tex;      /* tex.name is set at assembly */
    int ok;
} tex_entry;

struct gls_compiler {
    gls_diag diag;
    gls_root *roots;
    size_t nroots;
    gls_strmap units;        /* name -> gls_unit*; NULL-valued never stored */
    gls_strmap missing;      /* names already reported unknown -> (void*)1 */
    gls_strmap textures;     /* name -> tex_entry*                          */
    gls_unit **all;          /* every unit, for freeing                      */
    size_t nall, allcap;
    tex_entry **alltex;
    size_t nalltex, alltexcap;
    char **sources;
    uint32_t nsources, sourcescap;
    gls_unit **stack;        /* DFS path, for cycle messages                */
    size_t depth, stackcap;
    const char *gen_textures; /* where the build generates textures (hint) */
};

static const gls_loc noloc = {NULL, 0, 0};

gls_compiler *gls_compiler_new(FILE *diag_out)
{
    gls_compiler *c = calloc(1, sizeof *c);
    if (c)
        c->diag.out = diag_out;
    return c;
}

unsigned gls_compiler_errors(const gls_compiler *c) { return c->diag.errors; }

void gls_compiler_set_generated_textures(gls_compiler *c, const char *dir) { c->gen_textures = dir; }

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
    for (uint32_t i = 0; i < c->nsources; i++)
        free(c->sources[i]);
    gls_strmap_free(&c->units);
    for (size_t i = 0; i < c->missing.cap; i++)
        free(c->missing.vals[i]); /* the key is the value: one strdup each */
    gls_strmap_free(&c->missing);
    gls_strmap_free(&c->textures);
    free(c->roots);
    free(c->all);
    free(c->alltex);
    free(c->sources);
    free(c->stack);
    free(c);
}

static int push_ptr(void ***arr, size_t *n, size_t *cap, void *p)
{
    if (*n >= *cap) {
        size_t nc = *cap ? *cap * 2 : 16;
        void **a = realloc(*arr, nc * sizeof *a);
        if (!a)
            return -1;
        *arr = a;
        *cap = nc;
    }
    (*arr)[(*n)++] = p;
    return 0;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

int gls_compiler_add_root(gls_compiler *c, const char *path)
{
    gls_root r = {strdup(path), NULL};
    if (!r.path)
        return -1;
    if (!gls_is_dir(path)) {
        if (!gls_is_file(path)) {
            gls_error_at(&c->diag, noloc, "search root %s: no such directory or bundle", path);
            free(r.path);
            return -1;
        }
        gls_error err;
        r.lib = gls_bundle_read_file(path, &err);
        if (!r.lib) {
            gls_error_at(&c->diag, noloc, "search root %s", err.msg);
            free(r.path);
            return -1;
        }
    }
    void *p = realloc(c->roots, (c->nroots + 1) * sizeof *c->roots);
    if (!p) {
        free(r.path);
        gls_bundle_free(r.lib);
        return -1;
    }
    c->roots = p;
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

static uint32_t add_source(gls_compiler *c, const char *path)
{
    for (uint32_t i = 0; i < c->nsources; i++)
        if (strcmp(c->sources[i], path) == 0)
            return i;
    if (c->nsources >= c->sourcescap) {
        uint32_t nc = c->sourcescap ? c->sourcescap * 2 : 16;
        char **s = realloc(c->sources, nc * sizeof *s);
        if (!s)
            return GLS_NONE;
        c->sources = s;
        c->sourcescap = nc;
    }
    if (!(c->sources[c->nsources] = strdup(path)))
        return GLS_NONE;
    return c->nsources++;
}

/* "a.b.C" + root + ext -> "root/a/b/C.ext" */
static char *name_to_path(const char *root, const char *name, const char *ext)
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

static void list_roots(const gls_compiler *c, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = 0;
    for (size_t i = 0; i < c->nroots && k + 1 < n; i++)
        k += (size_t)snprintf(buf + k, n - k, "%s%s", i ? ", " : "", c->roots[i].path);
}

/* Compile a source file into a new unit named name. */
static gls_unit *unit_from_file(gls_compiler *c, const char *name, const char *path, gls_loc loc)
{
    char why[512];
    size_t len, mapped;
    char *text = gls_load_source(path, GLS_MAX_INPUT_BYTES, &len, &mapped, why, sizeof why);
    if (!text) {
        gls_error_at(&c->diag, loc, "%s", why);
        return NULL;
    }
    gls_unit *u = calloc(1, sizeof *u);
    uint32_t sf = add_source(c, path);
    if (!u || !(u->name = strdup(name)) || sf == GLS_NONE) {
        gls_release_file(text, mapped);
        gls_unit_free(u);
        gls_error_at(&c->diag, loc, "out of memory");
        return NULL;
    }
    u->src.path = c->sources[sf];
    u->src.text = text;
    u->src.len = len;
    u->src.mapped = mapped;
    u->src_file = sf;
    gls_compile_source(u, &c->diag);
    return u;
}

/* Import object oi of a library bundle as a unit: decode its code, turning
 * bundle indices back into by-name references and unit-local vertices. */
static gls_unit *unit_from_lib(gls_compiler *c, const gls_bundle *b, uint32_t oi, gls_loc loc)
{
    const gls_object *o = &b->objects[oi];
    gls_unit *u = calloc(1, sizeof *u);
    if (!u || !(u->name = strdup(o->name)))
        goto oom;
    u->src.path = "";
    size_t pos = 0;
    for (uint32_t k = 0; k < o->ninsn; k++) {
        gls_insn in;
        gls_insn_decode(o->code, o->code_len, &pos, &in); /* validated at load */
        uint32_t file = GLS_NONE, line = 0;
        if (o->src) {
            file = add_source(c, b->sources[o->src[k].file]);
            line = o->src[k].line;
            if (file == GLS_NONE)
                goto oom;
        }
        if (in.op == GLS_OP_CALL) {
            const char *nm = b->objects[in.u[0]].name;
            in.u[0] = gls_unit_add_ref(&u->refs, &u->nrefs, &u->refs_cap, nm, strlen(nm), loc);
            if (in.u[0] == GLS_NONE)
                goto oom;
        } else if (in.op == GLS_OP_TEXTURE) {
            const char *nm = b->textures[in.u[0]].name;
            in.u[0] = gls_unit_add_ref(&u->texrefs, &u->ntexrefs, &u->texrefs_cap, nm, strlen(nm), loc);
            if (in.u[0] == GLS_NONE)
                goto oom;
        } else if (in.op == GLS_OP_PRIM) {
            uint32_t n = in.u[1];
            gls_vec4 *np = realloc(u->pos, (size_t)(u->npos + n) * sizeof *np);
            if (!np)
                goto oom;
            u->pos = np;
            memcpy(u->pos + u->npos, b->pos + in.u[2], n * sizeof *np);
            in.u[2] = u->npos;
            u->npos += n;
            if (in.u[3] != GLS_NONE) {
                gls_rgba *nc = realloc(u->col, (size_t)(u->ncol + n) * sizeof *nc);
                if (!nc)
                    goto oom;
                u->col = nc;
                memcpy(u->col + u->ncol, b->col + in.u[3], n * sizeof *nc);
                in.u[3] = u->ncol;
                u->ncol += n;
            }
            if (in.u[4] != GLS_NONE) {
                gls_st *nt = realloc(u->tc, (size_t)(u->ntc + n) * sizeof *nt);
                if (!nt)
                    goto oom;
                u->tc = nt;
                memcpy(u->tc + u->ntc, b->tc + in.u[4], n * sizeof *nt);
                in.u[4] = u->ntc;
                u->ntc += n;
            }
        }
        u->src_file = file;
        if (gls_unit_emit(u, &in, line))
            goto oom;
        if (!o->src)
            u->lines[u->ninsn - 1].file = GLS_NONE;
    }
    u->pos_cap = u->npos;
    u->col_cap = u->ncol;
    u->tc_cap = u->ntc;
    return u;
oom:
    gls_unit_free(u);
    gls_error_at(&c->diag, loc, "out of memory");
    return NULL;
}

static int register_unit(gls_compiler *c, gls_unit *u)
{
    if (push_ptr((void ***)&c->all, &c->nall, &c->allcap, u) || gls_strmap_put(&c->units, u->name, u)) {
        gls_unit_free(u);
        return -1;
    }
    return 0;
}

/* The unit called name: already loaded, or found through the roots. */
static gls_unit *get_unit(gls_compiler *c, const char *name, gls_loc loc)
{
    gls_unit *u = gls_strmap_get(&c->units, name);
    if (u)
        return u;
    for (size_t i = 0; i < c->nroots; i++) {
        gls_root *r = &c->roots[i];
        if (r->lib) {
            uint32_t oi = gls_bundle_find_object(r->lib, name);
            if (oi != GLS_NONE) {
                u = unit_from_lib(c, r->lib, oi, loc);
                return u && register_unit(c, u) == 0 ? u : NULL;
            }
            continue;
        }
        char *path = name_to_path(r->path, name, ".scene");
        if (path && gls_is_file(path)) {
            u = unit_from_file(c, name, path, loc);
            free(path);
            return u && register_unit(c, u) == 0 ? u : NULL;
        }
        free(path);
    }
    if (!gls_strmap_get(&c->missing, name)) {
        char roots[1024];
        list_roots(c, roots, sizeof roots);
        gls_error_at(&c->diag, loc, "unknown object '%s' (searched: %s)", name, roots);
        char *key = strdup(name);
        if (key)
            gls_strmap_put(&c->missing, key, key);
    }
    return NULL;
}

static const char *const tex_exts[] = {".tga", ".png", ".jpg", ".jpeg", ".bmp"};

static tex_entry *get_texture(gls_compiler *c, const char *name, gls_loc loc)
{
    tex_entry *t = gls_strmap_get(&c->textures, name);
    if (t)
        return t->ok ? t : NULL;
    t = calloc(1, sizeof *t);
    if (!t || !(t->name = strdup(name)) || push_ptr((void ***)&c->alltex, &c->nalltex, &c->alltexcap, t)) {
        if (t)
            free(t->name);
        free(t);
        gls_error_at(&c->diag, loc, "out of memory");
        return NULL;
    }
    gls_strmap_put(&c->textures, t->name, t);
    for (size_t i = 0; i < c->nroots && !t->ok; i++) {
        gls_root *r = &c->roots[i];
        if (r->lib) {
            uint32_t ti = gls_bundle_find_texture(r->lib, name);
            if (ti == GLS_NONE)
                continue;
            const gls_texture *src = &r->lib->textures[ti];
            size_t bytes = (size_t)src->width * src->height * 4;
            t->tex = *src;
            t->tex.name = NULL;
            t->tex.rgba = malloc(bytes);
            if (!t->tex.rgba) {
                gls_error_at(&c->diag, loc, "out of memory");
                return NULL;
            }
            memcpy(t->tex.rgba, src->rgba, bytes);
            t->ok = 1;
            break;
        }
        for (size_t e = 0; e < sizeof tex_exts / sizeof tex_exts[0]; e++) {
            char *path = name_to_path(r->path, name, tex_exts[e]);
            if (path && gls_is_file(path)) {
                char why[512];
                if (gls_texture_decode(path, &t->tex, why, sizeof why) == 0)
                    t->ok = 1;
                else
                    gls_error_at(&c->diag, loc, "texture '%s': %s", name, why);
                free(path);
                return t->ok ? t : NULL;
            }
            free(path);
        }
    }
    if (!t->ok) {
        char roots[1024];
        list_roots(c, roots, sizeof roots);
        /* the scene library's textures are generated, not in its tree: say
           where, when the name is one of them */
        char *gen = c->gen_textures ? name_to_path(c->gen_textures, name, ".tga") : NULL;
        int there = gen && gls_is_file(gen);
        free(gen);
        gls_error_at(&c->diag, loc, "unknown texture '%s' (searched: %s; extensions .tga .png .jpg .jpeg .bmp)%s%s%s%s",
                     name, roots, there ? "; the build generates it in " : "", there ? c->gen_textures : "",
                     there ? ": add -I " : "", there ? c->gen_textures : "");
    }
    return t->ok ? t : NULL;
}

/* Depth-first walk over calls from u: loads callees and textures, detects
 * cycles.  Recursion depth is bounded by GLS_MAX_CALL_DEPTH. */
static void visit(gls_compiler *c, gls_unit *u)
{
    if (u->state)
        return;
    u->state = 1;
    if (push_ptr((void ***)&c->stack, &c->depth, &c->stackcap, u)) {
        gls_error_at(&c->diag, noloc, "out of memory");
        u->state = 2;
        return;
    }
    for (uint32_t i = 0; i < u->ntexrefs && !c->diag.stopped; i++)
        get_texture(c, u->texrefs[i].name, u->texrefs[i].loc);
    for (uint32_t i = 0; i < u->nrefs && !c->diag.stopped; i++) {
        gls_unit *callee = get_unit(c, u->refs[i].name, u->refs[i].loc);
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
            visit(c, callee);
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

static int cmp_unit(const void *a, const void *b)
{
    return strcmp((*(gls_unit *const *)a)->name, (*(gls_unit *const *)b)->name);
}

static int cmp_tex(const void *a, const void *b)
{
    return strcmp((*(tex_entry *const *)a)->name, (*(tex_entry *const *)b)->name);
}

/* Build the bundle from every unit with state 2 and every loaded texture
 * that a reachable unit uses (all loaded ones in library mode). */
static gls_bundle *assemble(gls_compiler *c, const gls_unit *top, int all_textures)
{
    gls_bundle *b = calloc(1, sizeof *b);
    gls_unit **units = malloc((c->nall ? c->nall : 1) * sizeof *units);
    tex_entry **texs = malloc((c->nalltex ? c->nalltex : 1) * sizeof *texs);
    uint32_t nu = 0, nt = 0;
    if (!b || !units || !texs)
        goto oom;
    for (size_t i = 0; i < c->nall; i++)
        if (c->all[i]->state == 2)
            units[nu++] = c->all[i];
    qsort(units, nu, sizeof *units, cmp_unit);
    /* which textures are used: all_textures, or referenced by a unit */
    gls_strmap used = {0};
    for (uint32_t i = 0; i < nu; i++)
        for (uint32_t k = 0; k < units[i]->ntexrefs; k++)
            gls_strmap_put(&used, units[i]->texrefs[k].name, (void *)1);
    for (size_t i = 0; i < c->nalltex; i++)
        if (c->alltex[i]->ok && (all_textures || gls_strmap_get(&used, c->alltex[i]->name)))
            texs[nt++] = c->alltex[i];
    gls_strmap_free(&used);
    qsort(texs, nt, sizeof *texs, cmp_tex);

    b->version = GLS_FORMAT_VERSION;
    b->nobjects = nu;
    b->ntextures = nt;
    b->objects = calloc(nu ? nu : 1, sizeof *b->objects);
    b->textures = calloc(nt ? nt : 1, sizeof *b->textures);
    if (!b->objects || !b->textures)
        goto oom;
    b->top = GLS_NONE;
    uint64_t npos = 0, ncol = 0, ntc = 0;
    for (uint32_t i = 0; i < nu; i++) {
        units[i]->final_index = i;
        if (units[i] == top)
            b->top = i;
        npos += units[i]->npos;
        ncol += units[i]->ncol;
        ntc += units[i]->ntc;
    }
    if (npos > GLS_MAX_VERTICES || ncol > GLS_MAX_VERTICES || ntc > GLS_MAX_VERTICES) {
        gls_error_at(&c->diag, noloc, "the scene has more than %u vertices", GLS_MAX_VERTICES);
        goto fail;
    }
    for (uint32_t i = 0; i < nt; i++) {
        b->textures[i] = texs[i]->tex;
        b->textures[i].name = strdup(texs[i]->name);
        b->textures[i].rgba = malloc((size_t)texs[i]->tex.width * texs[i]->tex.height * 4);
        if (!b->textures[i].name || !b->textures[i].rgba)
            goto oom;
        memcpy(b->textures[i].rgba, texs[i]->tex.rgba, (size_t)texs[i]->tex.width * texs[i]->tex.height * 4);
    }
    b->pos = malloc(npos * sizeof *b->pos + 1);
    b->col = malloc(ncol * sizeof *b->col + 1);
    b->tc = malloc(ntc * sizeof *b->tc + 1);
    if (!b->pos || !b->col || !b->tc)
        goto oom;
    for (uint32_t i = 0; i < nu; i++) {
        gls_unit *u = units[i];
        gls_object *o = &b->objects[i];
        uint32_t p0 = b->npos, c0 = b->ncol, t0 = b->ntex;
        /* a unit without colours has u->col == NULL: memcpy(NULL, 0) is undefined */
        if (u->npos)
            memcpy(b->pos + p0, u->pos, u->npos * sizeof *u->pos);
        if (u->ncol)
            memcpy(b->col + c0, u->col, u->ncol * sizeof *u->col);
        if (u->ntc)
            memcpy(b->tc + t0, u->tc, u->ntc * sizeof *u->tc);
        b->npos += u->npos;
        b->ncol += u->ncol;
        b->ntex += u->ntc;
        gls_buf code = {0};
        size_t pos = 0;
        int has_src = u->ninsn && u->lines[0].file != GLS_NONE;
        o->src = has_src ? malloc(u->ninsn * sizeof *o->src) : NULL;
        if (!(o->name = strdup(u->name)) || (has_src && !o->src))
            goto oom;
        for (uint32_t k = 0; k < u->ninsn; k++) {
            gls_insn in;
            gls_insn_decode(u->code.data, u->code.len, &pos, &in);
            /* relocate: the schema says which operand is which kind */
            uint32_t ui = 0;
            for (const char *s = gls_op_schema[in.op]; *s; s++) {
                if (*s == 'd')
                    continue;
                uint32_t *v = &in.u[ui++];
                switch (*s) {
                case 'o': *v = ((gls_unit *)gls_strmap_get(&c->units, u->refs[*v].name))->final_index; break;
                case 't': *v = gls_bundle_find_texture(b, u->texrefs[*v].name); break;
                case 'p': *v += p0; break;
                case 'c': if (*v != GLS_NONE) *v += c0; break;
                case 'x': if (*v != GLS_NONE) *v += t0; break;
                default: break;
                }
            }
            if (gls_insn_encode(&code, &in))
                goto oom;
            if (has_src)
                o->src[k] = u->lines[k];
        }
        o->code = code.data;
        o->code_len = (uint32_t)code.len;
        o->ninsn = u->ninsn;
    }
    b->nsources = c->nsources;
    b->sources = calloc(c->nsources ? c->nsources : 1, sizeof *b->sources);
    if (!b->sources)
        goto oom;
    for (uint32_t i = 0; i < c->nsources; i++)
        if (!(b->sources[i] = strdup(c->sources[i])))
            goto oom;
    b->features = gls_bundle_features(b);
    free(units);
    free(texs);
    return b;
oom:
    gls_error_at(&c->diag, noloc, "out of memory assembling the bundle");
fail:
    free(units);
    free(texs);
    gls_bundle_free(b);
    return NULL;
}

static int valid_object_name(const char *s)
{
    return gls_valid_name(s, strlen(s));
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

static void default_root(gls_compiler *c)
{
    if (c->nroots == 0)
        gls_compiler_add_root(c, ".");
}

int gls_compile_top(gls_compiler *c, const char *top, gls_bundle **out)
{
    *out = NULL;
    default_root(c);
    gls_unit *u = NULL;
    if (ends_with(top, ".scene")) {
        char *name = name_of_file(c, top);
        if (!name || !valid_object_name(name)) {
            gls_error_at(&c->diag, noloc,
                         "%s: cannot make an object name from this file name (use letters, digits and '_')", top);
            free(name);
            return -1;
        }
        if (!gls_is_file(top)) {
            gls_error_at(&c->diag, noloc, "%s: no such file", top);
            free(name);
            return -1;
        }
        u = unit_from_file(c, name, top, noloc);
        free(name);
        if (!u || register_unit(c, u))
            return -1;
    } else {
        if (!valid_object_name(top)) {
            gls_error_at(&c->diag, noloc, "'%s' is neither a .scene file nor a dotted object name", top);
            return -1;
        }
        u = get_unit(c, top, noloc);
        if (!u)
            return -1;
    }
    visit(c, u);
    if (c->diag.errors)
        return -1;
    gls_bundle *b = assemble(c, u, 0);
    if (!b)
        return -1;
    uint64_t nv = gls_bundle_expanded_vertices(b, b->top);
    if (nv > GLS_MAX_EXPANDED_VERTICES) {
        gls_error_at(&c->diag, noloc,
                     "%s draws more than %llu vertices once its calls are unrolled: too large to render",
                     u->name, (unsigned long long)GLS_MAX_EXPANDED_VERTICES);
        gls_bundle_free(b);
        return -1;
    }
    gls_error err;
    if (gls_bundle_validate(b, &err)) {
        gls_error_at(&c->diag, noloc, "internal error: built bundle fails validation: %s (format check line %d)",
                     err.msg, err.check_line);
        gls_bundle_free(b);
        return -1;
    }
    *out = b;
    return 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Collect the names of every .scene file and texture under dir. */
static int scan_dir(gls_compiler *c, const char *dir, const char *prefix, int depth)
{
    if (depth > 64) {
        gls_error_at(&c->diag, noloc, "%s: directories nested too deeply", dir);
        return -1;
    }
    DIR *d = opendir(dir);
    if (!d) {
        gls_error_at(&c->diag, noloc, "cannot read directory %s", dir);
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
        if (!s || push_ptr((void ***)&names, &n, &cap, s)) {
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
            if (valid_object_name(qual))
                rc |= scan_dir(c, path, qual, depth + 1);
        } else {
            char *dot = strrchr(qual, '.');
            char *base = strrchr(names[i], '.');
            int known = 0;
            for (size_t k = 0; base && k < sizeof tex_exts / sizeof tex_exts[0]; k++)
                known |= strcmp(base, tex_exts[k]) == 0;
            if (base && (known || strcmp(base, ".scene") == 0) && memchr(names[i], '.', (size_t)(base - names[i]))) {
                /* "a.b.scene" would be named a.b and looked up as a/b.scene */
                gls_error_at(&c->diag, noloc, "%s: a file name must be an identifier before its extension", path);
                rc = -1;
            } else if (base && dot) {
                *dot = 0;
                if (strcmp(base, ".scene") == 0 && valid_object_name(qual))
                    get_unit(c, qual, noloc);
                else
                    for (size_t k = 0; k < sizeof tex_exts / sizeof tex_exts[0]; k++)
                        if (strcmp(base, tex_exts[k]) == 0 && valid_object_name(qual))
                            get_texture(c, qual, noloc);
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
        gls_error_at(&c->diag, noloc, "--lib %s: not a directory", root);
        return -1;
    }
    /* the library root is searched first, then the other roots */
    gls_root r = {strdup(root), NULL};
    gls_root *nr = realloc(c->roots, (c->nroots + 1) * sizeof *nr);
    if (!r.path || !nr) {
        free(r.path);
        return -1;
    }
    c->roots = nr;
    memmove(c->roots + 1, c->roots, c->nroots * sizeof *c->roots);
    c->roots[0] = r;
    c->nroots++;
    scan_dir(c, root, "", 0);
    for (size_t i = 0; i < c->nall && !c->diag.stopped; i++)
        visit(c, c->all[i]);
    if (c->diag.errors)
        return -1;
    gls_bundle *b = assemble(c, NULL, 1);
    if (!b)
        return -1;
    gls_error err;
    if (gls_bundle_validate(b, &err)) {
        gls_error_at(&c->diag, noloc, "internal error: built bundle fails validation: %s", err.msg);
        gls_bundle_free(b);
        return -1;
    }
    *out = b;
    return 0;
}
