/* Landmark and class names (spec/bundle.md 7.9, 12.2): the MARK_NAMES
 * table and the `mark` and `class` instructions that use it.  A landmark
 * is looked up by its name within its object's instance, so one object
 * places a name at most once; an object has at most one class.  The table
 * lists each name once, in order, and only names some mark or class uses
 * (one encoding per content). */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"

void gls_fail(gls_error *err, int line, const char *fmt, ...);
#define FAIL(...) do { gls_fail(err, __LINE__, __VA_ARGS__); goto fail; } while (0)

int gls_check_mark_names(const gls_bundle *b, gls_error *err);

int gls_valid_mark_name(const char *s, size_t n)
{
    if (!s || n == 0 || n > GLS_MAX_MARK_NAME_BYTES)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' ||
                 ch == '.' || ch == '-';
        if (!ok)
            return 0;
    }
    return 1;
}

const char *gls_object_class(const gls_bundle *b, uint32_t oi)
{
    const gls_object *o = &b->objects[oi];
    size_t pos = 0;
    gls_insn in;
    while (pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0)
        if (in.op == GLS_OP_CLASS && in.u[GLS_ARG_CLASS_NAME] < b->nmarknames)
            return b->marknames[in.u[GLS_ARG_CLASS_NAME]];
    return NULL;
}

/* Runs after every object's code has been checked (check_code): the
 * MARKNAME and CLASSNAME operands are in range. */
int gls_check_mark_names(const gls_bundle *b, gls_error *err)
{
    uint32_t *last = NULL; /* per name: 1 + the object that placed it last */
    uint8_t *used = NULL;
    for (uint32_t i = 0; i < b->nmarknames; i++) {
        const char *n = b->marknames[i];
        if (!n || !gls_valid_mark_name(n, strlen(n)))
            FAIL("landmark name %u is not a valid name ([A-Za-z0-9_.-], 1 to %u bytes)", i, GLS_MAX_MARK_NAME_BYTES);
        if (i && strcmp(b->marknames[i - 1], n) >= 0)
            FAIL("landmark name table not sorted or has a duplicate at %s", n);
    }
    if (!b->nmarknames)
        return 0;
    last = calloc(b->nmarknames, sizeof *last);
    used = calloc(b->nmarknames, 1);
    if (!last || !used)
        FAIL("out of memory");
    for (uint32_t oi = 0; oi < b->nobjects; oi++) {
        const gls_object *o = &b->objects[oi];
        uint32_t nclass = 0;
        size_t pos = 0;
        gls_insn in;
        for (uint32_t k = 0; pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0; k++) {
            if (in.op == GLS_OP_CLASS) {
                if (nclass++)
                    FAIL("object %s, instruction %u (class): the object has a second class %s", o->name, k,
                         b->marknames[in.u[GLS_ARG_CLASS_NAME]]);
                used[in.u[GLS_ARG_CLASS_NAME]] = 1;
                continue;
            }
            int arg = gls_op_find(in.op, GLS_KIND_MARKNAME);
            if (arg < 0)
                continue;
            uint32_t v = in.u[arg];
            if (last[v] == oi + 1)
                FAIL("object %s, instruction %u (mark): landmark %s is placed twice in the object", o->name, k,
                     b->marknames[v]);
            last[v] = oi + 1;
            used[v] = 1;
        }
    }
    for (uint32_t i = 0; i < b->nmarknames; i++)
        if (!used[i])
            FAIL("landmark name %s: no mark or class uses it", b->marknames[i]);
    free(last), free(used);
    return 0;
fail:
    free(last), free(used);
    return -1;
}
