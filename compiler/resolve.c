/* Name resolution (spec/language.md 1.3, 2.1): the object or texture a
 * name stands for, found through the roots in order, compiled from its
 * .scene file, imported from a bundle or decoded from an image, each once
 * per run; and the list of source files read. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "fileio.h"
#include "linker.h"

int gls_valid_object_name(const char *s)
{
    return gls_valid_name(s, strlen(s));
}

uint32_t gls_add_source(gls_compiler *c, const char *path)
{
    for (uint32_t i = 0; i < c->nsources; i++)
        if (strcmp(c->sources[i], path) == 0)
            return i;
    if (gls_grow(&c->sources, &c->sourcescap, (size_t)c->nsources + 1, sizeof *c->sources))
        return GLS_NONE;
    if (!(c->sources[c->nsources] = strdup(path)))
        return GLS_NONE;
    return c->nsources++;
}

/* Compile a source file into a new unit named name. */
gls_unit *gls_unit_from_file(gls_compiler *c, const char *name, const char *path, gls_loc loc)
{
    char why[512];
    size_t len, mapped;
    char *text = gls_load_source(path, GLS_MAX_INPUT_BYTES, &len, &mapped, why, sizeof why);
    if (!text) {
        gls_error_at(&c->diag, loc, "%s", why);
        return NULL;
    }
    gls_unit *u = calloc(1, sizeof *u);
    uint32_t sf = gls_add_source(c, path);
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
    u->is_top = c->top_name && strcmp(name, c->top_name) == 0;
    gls_compile_source(u, &c->diag);
    return u;
}

int gls_register_unit(gls_compiler *c, gls_unit *u)
{
    if (gls_push_ptr((void ***)&c->all, &c->nall, &c->allcap, u) || gls_strmap_put(&c->units, u->name, u)) {
        gls_unit_free(u);
        return -1;
    }
    return 0;
}

/* The unit called name: already loaded, or found through the roots. */
gls_unit *gls_get_unit(gls_compiler *c, const char *name, gls_loc loc)
{
    gls_unit *u = gls_strmap_get(&c->units, name);
    if (u)
        return u;
    for (size_t i = 0; i < c->nroots; i++) {
        gls_root *r = &c->roots[i];
        if (r->lib) {
            uint32_t oi = gls_bundle_find_object(r->lib, name);
            if (oi != GLS_NONE) {
                u = gls_unit_from_lib(c, r->lib, oi, loc);
                return u && gls_register_unit(c, u) == 0 ? u : NULL;
            }
            continue;
        }
        char *path = gls_name_to_path(r->path, name, ".scene");
        if (path && gls_is_file(path)) {
            u = gls_unit_from_file(c, name, path, loc);
            free(path);
            return u && gls_register_unit(c, u) == 0 ? u : NULL;
        }
        free(path);
    }
    if (!gls_strmap_get(&c->missing, name)) {
        char roots[1024];
        gls_list_roots(c, roots, sizeof roots);
        gls_error_at(&c->diag, loc, "unknown object '%s' (searched: %s)", name, roots);
        char *key = strdup(name);
        if (key)
            gls_strmap_put(&c->missing, key, key);
    }
    return NULL;
}

const char *const gls_tex_exts[GLS_NTEX_EXTS] = {".tga", ".png", ".jpg", ".jpeg", ".bmp"};

tex_entry *gls_get_texture(gls_compiler *c, const char *name, gls_loc loc)
{
    tex_entry *t = gls_strmap_get(&c->textures, name);
    if (t)
        return t->ok ? t : NULL;
    t = calloc(1, sizeof *t);
    if (!t || !(t->name = strdup(name)) || gls_push_ptr((void ***)&c->alltex, &c->nalltex, &c->alltexcap, t)) {
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
        for (size_t e = 0; e < sizeof gls_tex_exts / sizeof gls_tex_exts[0]; e++) {
            char *path = gls_name_to_path(r->path, name, gls_tex_exts[e]);
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
        gls_list_roots(c, roots, sizeof roots);
        gls_error_at(&c->diag, loc, "unknown texture '%s' (searched: %s; extensions .tga .png .jpg .jpeg .bmp)", name,
                     roots);
    }
    return t->ok ? t : NULL;
}
