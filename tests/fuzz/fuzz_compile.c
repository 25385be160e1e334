/* libFuzzer target: the scene compiler's front end (scanner, parser,
 * semantic checks, loops) on arbitrary bytes as one .scene file; a file
 * that declares parameters is run a second time with other values, as a
 * call with values would (template.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "unit.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static FILE *sink;
    if (!sink)
        sink = fopen("/dev/null", "w");
    gls_unit *u = calloc(1, sizeof *u);
    char *text = malloc(size + 1);
    if (!u || !text) {
        free(u);
        free(text);
        return 0;
    }
    memcpy(text, data, size);
    text[size] = 0; /* the sentinel the loader guarantees */
    u->name = strdup("Fuzz");
    u->src.path = "fuzz.scene";
    u->src.text = text;
    u->src.len = size;
    gls_diag d = {.out = sink, .dedupe = 1};
    gls_tree tree = {0};
    gls_compile_source_keep(u, &d, &tree, NULL);
    if (tree.nparams) {
        gls_named binding[GLS_MAX_PARAMS];
        char names[GLS_MAX_PARAMS][64];
        for (unsigned i = 0; i < tree.nparams; i++) {
            snprintf(names[i], sizeof names[i], "%.*s", (int)tree.pnames[i].len, tree.pnames[i].p);
            binding[i] = (gls_named){names[i], tree.defaults[i] * 2 + 1, {NULL, 0, 0}};
        }
        gls_unit *v = calloc(1, sizeof *v);
        if (v) {
            v->name = strdup("Fuzz(values)");
            v->src = u->src;
            v->src_borrowed = 1;
            gls_run_tree(v, &d, &tree, binding, tree.nparams, NULL);
            gls_unit_free(v);
        }
        gls_tree_free(&tree);
    }
    gls_diag_free(&d);
    gls_unit_free(u);
    return 0;
}
