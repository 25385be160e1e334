/* Encoders of the instance and class outputs (out_gt.h). */
#include <stdlib.h>
#include <string.h>
#include "out_gt.h"
#include "outputs.h"

/* The id of a pass value (scene instance + 1, 0: none). */
static uint32_t id_of(const gls_gt_table *t, uint32_t v) { return v && v <= t->ninst ? t->id[v - 1] : 0; }

void gls_ids16(const uint32_t *inst, const gls_gt_table *t, int klass, size_t n, uint16_t *px)
{
    for (size_t i = 0; i < n; i++) {
        uint32_t id = id_of(t, inst[i]);
        px[i] = (uint16_t)(klass && id ? t->class_id[id - 1] : id);
    }
}

int gls_encode_ids_png(const uint32_t *inst, const gls_gt_table *t, int klass, uint32_t w, uint32_t h,
                       gls_buf *out)
{
    size_t n = (size_t)w * h;
    uint16_t *px = malloc((n ? n : 1) * sizeof *px);
    if (!px)
        return -1;
    gls_ids16(inst, t, klass, n, px);
    int rc = gls_encode_png16_gray(px, w, h, out);
    free(px);
    return rc;
}

/* Pixels per id (index 0: background). */
static uint64_t *count_ids(const uint32_t *inst, const gls_gt_table *t, size_t n)
{
    uint64_t *cnt = calloc((size_t)t->nids + 1, sizeof *cnt);
    for (size_t i = 0; cnt && i < n; i++)
        cnt[id_of(t, inst[i])]++;
    return cnt;
}

static int put_classes(gls_buf *b, const gls_gt_table *t, const char *key, const char *indent)
{
    if (gls_buf_printf(b, "  \"%s\": [", key))
        return -1;
    for (uint32_t c = 0; c < t->nclasses; c++)
        if (gls_buf_printf(b, "%s\n%s{\"id\": %u, \"name\": ", c ? "," : "", indent, c + 1) ||
            gls_buf_quoted(b, t->classes[c], 1) || gls_buf_printf(b, "}"))
            return -1;
    return gls_buf_printf(b, "%s]", t->nclasses ? "\n  " : "");
}

int gls_encode_instances_json(const uint32_t *inst, const gls_gt_table *t, uint32_t frame, const char *camera,
                              uint32_t w, uint32_t h, gls_buf *out)
{
    uint64_t *cnt = count_ids(inst, t, (size_t)w * h);
    if (!cnt)
        return -1;
    int e = gls_buf_printf(out, "{\n  \"frame\": %u,\n  \"camera\": ", frame) || gls_buf_quoted(out, camera, 1) ||
            gls_buf_printf(out, ",\n  \"width\": %u,\n  \"height\": %u,\n  \"instances\": [", w, h);
    int first = 1;
    for (uint32_t id = 1; id <= t->nids && !e; id++) {
        if (!cnt[id])
            continue;
        e = gls_buf_printf(out, "%s\n    {\"id\": %u, \"path\": ", first ? "" : ",", id) ||
            gls_buf_quoted(out, t->path[id - 1], 1);
        if (!e && t->name[id - 1])
            e = gls_buf_printf(out, ", \"name\": ") || gls_buf_quoted(out, t->name[id - 1], 1);
        e = e || gls_buf_printf(out, ", \"object\": ") || gls_buf_quoted(out, t->object[id - 1], 1) ||
            gls_buf_printf(out, ", \"class\": ") ||
            gls_buf_quoted(out, t->classes[t->class_id[id - 1] - 1], 1) ||
            gls_buf_printf(out, ", \"class_id\": %u, \"pixels\": %llu}", t->class_id[id - 1],
                           (unsigned long long)cnt[id]);
        first = 0;
    }
    e = e || gls_buf_printf(out, "%s],\n", first ? "" : "\n  ") || put_classes(out, t, "classes", "    ") ||
        gls_buf_printf(out, "\n}\n");
    free(cnt);
    return e ? -1 : 0;
}

/* Column-major runs of each id: RLE as COCO defines it (the mask
 * flattened column by column, x * h + y; counts alternate, zeros first).
 * Two passes over the image: the runs of each id counted, then placed. */
typedef struct {
    uint64_t *start;  /* of each id's runs, at off[id] .. off[id + 1] - 1 */
    uint64_t *end;
    uint64_t *off;
    uint32_t *box;    /* per id: x0 y0 x1 y1 */
} runs;

static int make_runs(const uint32_t *inst, const gls_gt_table *t, uint32_t w, uint32_t h, runs *r)
{
    size_t nid = (size_t)t->nids + 1;
    memset(r, 0, sizeof *r);
    r->off = calloc(nid + 1, sizeof *r->off);
    r->box = malloc(nid * 4 * sizeof *r->box);
    if (!r->off || !r->box)
        return -1;
    for (size_t id = 0; id < nid; id++)
        r->box[4 * id] = r->box[4 * id + 1] = UINT32_MAX, r->box[4 * id + 2] = r->box[4 * id + 3] = 0;
    uint32_t prev = 0;
    for (uint32_t x = 0; x < w; x++)
        for (uint32_t y = 0; y < h; y++) {
            uint32_t id = id_of(t, inst[(size_t)y * w + x]);
            if (id && id != prev)
                r->off[id + 1]++;
            prev = id;
            uint32_t *b = r->box + 4 * id;
            if (x < b[0])
                b[0] = x;
            if (y < b[1])
                b[1] = y;
            if (x > b[2])
                b[2] = x;
            if (y > b[3])
                b[3] = y;
        }
    for (size_t id = 1; id <= nid; id++)
        r->off[id] += r->off[id - 1];
    uint64_t total = r->off[nid];
    r->start = malloc((total ? total : 1) * sizeof *r->start);
    r->end = malloc((total ? total : 1) * sizeof *r->end);
    uint64_t *at = malloc(nid * sizeof *at);
    if (!r->start || !r->end || !at) {
        free(at);
        return -1;
    }
    memcpy(at, r->off, nid * sizeof *at);
    prev = 0;
    uint64_t j = 0;
    for (uint32_t x = 0; x < w; x++)
        for (uint32_t y = 0; y < h; y++, j++) {
            uint32_t id = id_of(t, inst[(size_t)y * w + x]);
            if (id && id != prev)
                r->start[at[id]++] = j;
            if (id)
                r->end[at[id] - 1] = j + 1;
            prev = id;
        }
    free(at);
    return 0;
}

static void free_runs(runs *r)
{
    free(r->start), free(r->end), free(r->off), free(r->box);
}

int gls_encode_coco(const uint32_t *inst, const gls_gt_table *t, uint32_t frame, const char *image, uint32_t w,
                    uint32_t h, gls_buf *out)
{
    runs r;
    if (make_runs(inst, t, w, h, &r)) {
        free_runs(&r);
        return -1;
    }
    uint64_t n = (uint64_t)w * h;
    int e = gls_buf_printf(out, "{\n  \"images\": [{\"id\": %u, \"file_name\": ", frame) ||
            gls_buf_quoted(out, image, 1) ||
            gls_buf_printf(out, ", \"width\": %u, \"height\": %u}],\n", w, h) ||
            put_classes(out, t, "categories", "    ") || gls_buf_printf(out, ",\n  \"annotations\": [");
    int first = 1;
    for (uint32_t id = 1; id <= t->nids && !e; id++) {
        uint64_t a = r.off[id], b = r.off[id + 1], area = 0;
        if (a == b)
            continue;
        for (uint64_t k = a; k < b; k++)
            area += r.end[k] - r.start[k];
        const uint32_t *bx = r.box + 4 * id;
        e = gls_buf_printf(out,
                           "%s\n    {\"id\": %u, \"image_id\": %u, \"category_id\": %u, \"iscrowd\": 1, "
                           "\"area\": %llu, \"bbox\": [%u, %u, %u, %u], "
                           "\"segmentation\": {\"size\": [%u, %u], \"counts\": [",
                           first ? "" : ",", id, frame, t->class_id[id - 1], (unsigned long long)area, bx[0], bx[1],
                           bx[2] - bx[0] + 1, bx[3] - bx[1] + 1, h, w);
        uint64_t pos = 0;
        for (uint64_t k = a; k < b && !e; k++) {
            e = gls_buf_printf(out, "%s%llu, %llu", k > a ? ", " : "", (unsigned long long)(r.start[k] - pos),
                               (unsigned long long)(r.end[k] - r.start[k]));
            pos = r.end[k];
        }
        if (!e && pos < n)
            e = gls_buf_printf(out, ", %llu", (unsigned long long)(n - pos));
        e = e || gls_buf_printf(out, "]}}");
        first = 0;
    }
    e = e || gls_buf_printf(out, "%s]\n}\n", first ? "" : "\n  ");
    free_runs(&r);
    return e ? -1 : 0;
}
