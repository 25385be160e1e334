/* KITTI label and JSON encoders of the boxes (out_boxes.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "gt_table.h"
#include "out_boxes.h"

int gls_box_names_init(gls_box_names *nm, const gls_bundle *b, const gls_scene *s)
{
    nm->scene = s;
    nm->nobjects = b->nobjects;
    nm->objects = calloc(b->nobjects ? b->nobjects : 1, sizeof *nm->objects);
    nm->declared = calloc(b->nobjects ? b->nobjects : 1, sizeof *nm->declared);
    if (!nm->objects || !nm->declared) {
        gls_box_names_free(nm);
        return -1;
    }
    for (uint32_t i = 0; i < b->nobjects; i++) {
        const char *c = gls_object_class(b, i);
        if (!(nm->objects[i] = strdup(b->objects[i].name)) || (c && !(nm->declared[i] = strdup(c)))) {
            gls_box_names_free(nm);
            return -1;
        }
    }
    return 0;
}

void gls_box_names_free(gls_box_names *nm)
{
    for (uint32_t i = 0; i < nm->nobjects; i++) {
        if (nm->objects)
            free(nm->objects[i]);
        if (nm->declared)
            free(nm->declared[i]);
    }
    free(nm->objects);
    free(nm->declared);
    nm->objects = nm->declared = NULL;
}

static const char *object_of(const gls_box_names *nm, uint32_t i)
{
    return nm->objects[nm->scene->protos[nm->scene->inst[i].proto].object];
}

void gls_box_class(const gls_box_names *nm, uint32_t i, char *buf, size_t len)
{
    gls_gt_class_of(nm->scene, i, (const char *const *)nm->objects, (const char *const *)nm->declared, buf, len);
}

/* The instance's name, or its nearest named ancestor's; NULL if none. */
static const char *name_of(const gls_scene *s, uint32_t i)
{
    for (; i != GLS_NONE; i = s->inst[i].parent)
        if (s->inst[i].name)
            return s->inst[i].name;
    return NULL;
}

static int num(gls_buf *b, const char *before, double v)
{
    char s[48];
    gls_fmt_double(s, sizeof s, v);
    return gls_buf_printf(b, "%s%s", before, s);
}

int gls_encode_boxes_kitti(const gls_box *b, size_t n, const gls_box_names *nm, gls_buf *out)
{
    for (size_t j = 0; j < n; j++) {
        char cls[256];
        gls_box_class(nm, b[j].inst, cls, sizeof cls);
        const gls_box *x = &b[j];
        int e = gls_buf_printf(out, "%s", cls) || num(out, " ", x->truncated) ||
                gls_buf_printf(out, " %d", x->occluded) || num(out, " ", x->alpha);
        for (int k = 0; k < 4; k++)
            e = e || num(out, " ", x->bbox[k]);
        for (int k = 0; k < 3; k++)
            e = e || num(out, " ", x->dims[k]);
        for (int k = 0; k < 3; k++)
            e = e || num(out, " ", x->loc[k]);
        if (e || num(out, " ", x->ry) || gls_buf_put(out, "\n", 1))
            return -1;
    }
    return 0;
}

/* "key": [v...], or the bare array when key is NULL */
static int vec(gls_buf *out, const char *key, const double *v, int n)
{
    int e = key ? gls_buf_printf(out, "\"%s\": [", key) : gls_buf_put(out, "[", 1);
    for (int k = 0; k < n; k++)
        e = e || num(out, k ? ", " : "", v[k]);
    return e || gls_buf_put(out, "]", 1);
}

int gls_encode_boxes_json(const gls_box *b, size_t n, const gls_box_names *nm, const gls_camera *c,
                          const char *camera, uint32_t frame, gls_buf *out)
{
    static const char axis[3] = {'x', 'y', 'z'};
    /* the camera's name is a file name: anything may be in it; object,
     * class and instance names are quoted too, whatever they hold */
    int e = gls_buf_printf(out, "{\n  \"camera\": ") || gls_buf_quoted(out, camera, 1) ||
            gls_buf_printf(out, ",\n  \"frame\": %u,\n  \"width\": %u,\n  \"height\": %u,\n  \"boxes\": [", frame,
                           c->width, c->height);
    for (size_t j = 0; j < n && !e; j++) {
        const gls_box *x = &b[j];
        char cls[256];
        gls_box_class(nm, x->inst, cls, sizeof cls);
        const char *name = name_of(nm->scene, x->inst);
        e = gls_buf_printf(out, "%s\n    {\"id\": %u, \"instance\": %u, \"object\": ", j ? "," : "", x->inst + 1,
                           x->inst) ||
            gls_buf_quoted(out, object_of(nm, x->inst), 1) || gls_buf_printf(out, ", \"class\": ") ||
            gls_buf_quoted(out, cls, 1) || gls_buf_printf(out, ", \"name\": ") ||
            (name ? gls_buf_quoted(out, name, 1) : gls_buf_printf(out, "null")) || gls_buf_printf(out, ",\n") ||
            gls_buf_printf(out, "     \"pixels\": %llu, \"pixels_alone\": %llu, ", (unsigned long long)x->pixels,
                           (unsigned long long)x->alone) ||
            num(out, "\"visible_fraction\": ", x->visible) || num(out, ", \"truncated\": ", x->truncated) ||
            gls_buf_printf(out, ", \"occluded\": %d,\n     ", x->occluded) || num(out, "\"alpha\": ", x->alpha) ||
            gls_buf_printf(out, ", ") || vec(out, "bbox", x->bbox, 4) || gls_buf_printf(out, ",\n     ") ||
            vec(out, "dimensions", x->dims, 3) || gls_buf_printf(out, ", ") || vec(out, "location", x->loc, 3) ||
            num(out, ", \"rotation_y\": ", x->ry) ||
            gls_buf_printf(out, ",\n     \"axes\": {\"up\": \"%c\", \"length\": \"%c\", \"width\": \"%c\"},\n"
                                "     \"corners\": [",
                           axis[x->up], axis[x->len], axis[x->wid]);
        for (int k = 0; k < 8 && !e; k++)
            e = gls_buf_printf(out, "%s", k ? ", " : "") || vec(out, NULL, x->corners[k], 3);
        e = e || gls_buf_printf(out, "]}");
    }
    return e || gls_buf_printf(out, "%s]\n}\n", n ? "\n  " : "") ? -1 : 0;
}
