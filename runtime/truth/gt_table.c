/* The instance and class ids of a run (gt_table.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "gt_table.h"

void gls_gt_package_of(const char *object, char *buf, size_t len)
{
    /* a specialised object's name ends in its values, "pkg.Sign(h=1.5)":
     * the package is what comes before the last dot of the name itself */
    size_t n = strcspn(object, "(");
    size_t dot = n;
    while (dot > 0 && object[dot - 1] != '.')
        dot--;
    if (dot > 1)
        n = dot - 1;
    if (len == 0)
        return;
    if (n >= len)
        n = len - 1;
    memcpy(buf, object, n);
    buf[n] = 0;
}

void gls_gt_class_of(const gls_scene *s, uint32_t i, const char *const *names, const char *const *declared,
                     char *buf, size_t len)
{
    for (uint32_t j = i; j != GLS_NONE; j = s->inst[j].parent)
        if (declared[s->inst[j].object]) {
            if (len)
                snprintf(buf, len, "%s", declared[s->inst[j].object]);
            return;
        }
    gls_gt_package_of(names[s->inst[i].object], buf, len);
}

/* Instances sorted by (parent, object, index): the k of OBJECT#k. */
typedef struct {
    uint32_t parent, object, index;
} call_key;

static int key_cmp(const void *a, const void *b)
{
    const call_key *x = a, *y = b;
    if (x->parent != y->parent)
        return x->parent < y->parent ? -1 : 1;
    if (x->object != y->object)
        return x->object < y->object ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

static int str_cmp(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* Instance i's call path, from k[] (k[0] unused: the top has no #k). */
static char *call_path(const gls_bundle *b, const gls_scene *s, const uint32_t *k, uint32_t i)
{
    gls_buf out = {0};
    uint32_t depth = 0;
    for (uint32_t j = i; j != GLS_NONE; j = s->inst[j].parent)
        depth++;
    uint32_t *chain = malloc(depth * sizeof *chain);
    if (!chain)
        return NULL;
    uint32_t d = depth;
    for (uint32_t j = i; j != GLS_NONE; j = s->inst[j].parent)
        chain[--d] = j;
    int bad = 0;
    for (d = 0; d < depth && !bad; d++) {
        const char *obj = b->objects[s->inst[chain[d]].object].name;
        bad = d ? gls_buf_printf(&out, " > %s#%u", obj, k[chain[d]]) : gls_buf_printf(&out, "%s", obj);
    }
    free(chain);
    if (bad || gls_buf_put(&out, "", 1)) {
        free(out.data);
        return NULL;
    }
    return (char *)out.data;
}

int gls_gt_table_build(gls_gt_table *t, const gls_bundle *b, const gls_scene *s, uint32_t *count)
{
    memset(t, 0, sizeof *t);
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->ninst; i++)
        n += s->inst[i].nitems > 0;
    *count = n;
    if (n > GLS_GT_MAX_IDS)
        return 1;
    t->ninst = s->ninst;
    t->nids = n;
    size_t m = n ? n : 1;
    t->id = calloc(s->ninst ? s->ninst : 1, sizeof *t->id);
    t->path = calloc(m, sizeof *t->path);
    t->name = calloc(m, sizeof *t->name);
    t->object = calloc(m, sizeof *t->object);
    t->class_id = calloc(m, sizeof *t->class_id);
    t->classes = calloc(m, sizeof *t->classes);
    uint32_t *k = calloc(s->ninst ? s->ninst : 1, sizeof *k);
    call_key *keys = malloc((s->ninst ? s->ninst : 1) * sizeof *keys);
    char **cls = calloc(m, sizeof *cls); /* per id - 1, before numbering */
    const char **names = calloc(b->nobjects ? b->nobjects : 1, sizeof *names);
    const char **declared = calloc(b->nobjects ? b->nobjects : 1, sizeof *declared);
    int rc = -1;
    if (!t->id || !t->path || !t->name || !t->object || !t->class_id || !t->classes || !k || !keys || !cls ||
        !names || !declared)
        goto out;
    for (uint32_t oi = 0; oi < b->nobjects; oi++)
        names[oi] = b->objects[oi].name, declared[oi] = gls_object_class(b, oi);
    for (uint32_t i = 0; i < s->ninst; i++)
        keys[i] = (call_key){s->inst[i].parent, s->inst[i].object, i};
    qsort(keys, s->ninst, sizeof *keys, key_cmp);
    for (uint32_t j = 0; j < s->ninst; j++)
        k[keys[j].index] = j && keys[j - 1].parent == keys[j].parent && keys[j - 1].object == keys[j].object
                               ? k[keys[j - 1].index] + 1
                               : 1;
    uint32_t id = 0;
    for (uint32_t i = 0; i < s->ninst; i++) {
        if (!s->inst[i].nitems)
            continue;
        t->id[i] = (uint16_t)++id;
        const char *obj = b->objects[s->inst[i].object].name;
        char c[256];
        gls_gt_class_of(s, i, names, declared, c, sizeof c);
        t->path[id - 1] = call_path(b, s, k, i);
        t->object[id - 1] = strdup(obj);
        cls[id - 1] = strdup(c);
        if (s->inst[i].name)
            t->name[id - 1] = strdup(s->inst[i].name);
        if (!t->path[id - 1] || !t->object[id - 1] || !cls[id - 1] || (s->inst[i].name && !t->name[id - 1]))
            goto out;
    }
    /* the class table: the distinct names, sorted */
    for (uint32_t j = 0; j < n; j++)
        t->classes[j] = cls[j];
    qsort(t->classes, n, sizeof *t->classes, str_cmp);
    uint32_t nc = 0;
    for (uint32_t j = 0; j < n; j++)
        if (nc == 0 || strcmp(t->classes[nc - 1], t->classes[j]) != 0)
            t->classes[nc++] = t->classes[j];
    t->nclasses = nc;
    for (uint32_t j = 0; j < n; j++) {
        char **hit = bsearch(&cls[j], t->classes, nc, sizeof *t->classes, str_cmp);
        t->class_id[j] = (uint16_t)(hit - t->classes + 1);
    }
    /* the table owns one copy of each class name: free the duplicates */
    for (uint32_t j = 0; j < n; j++) {
        if (cls[j] != t->classes[t->class_id[j] - 1])
            free(cls[j]);
        cls[j] = NULL;
    }
    rc = 0;
out:
    if (rc) {
        for (uint32_t j = 0; cls && j < n; j++)
            free(cls[j]);
        t->nclasses = 0; /* the names were cls's */
        gls_gt_table_free(t);
    }
    free(cls);
    free(keys);
    free(k);
    free(names);
    free(declared);
    return rc;
}

void gls_gt_table_free(gls_gt_table *t)
{
    for (uint32_t j = 0; j < t->nids; j++) {
        if (t->path)
            free(t->path[j]);
        if (t->name)
            free(t->name[j]);
        if (t->object)
            free(t->object[j]);
    }
    for (uint32_t j = 0; t->classes && j < t->nclasses; j++)
        free(t->classes[j]);
    free(t->id);
    free(t->path);
    free(t->name);
    free(t->object);
    free(t->class_id);
    free(t->classes);
    memset(t, 0, sizeof *t);
}
