/* libFuzzer target: the scene compiler's front end (scanner, parser,
 * semantic checks) on arbitrary bytes as one .scene file. */
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
    gls_diag d = {.out = sink};
    gls_compile_source(u, &d);
    gls_unit_free(u);
    return 0;
}
