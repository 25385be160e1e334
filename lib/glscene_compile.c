/* glscene_compile (include/glscene.h): what glsc does for a scene, with
 * the compiler's diagnostics captured into the error instead of printed
 * (the library never writes to the standard streams). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "atomic_write.h"
#include "compile.h"
#include "glscene_internal.h"
#include "mkdirs.h"

/* The captured diagnostics into e: whole if they fit, else the complete
 * lines that fit (a first line longer than e->message is cut). */
static void diagnostics_to_error(const char *text, glscene_error *e)
{
    size_t len = strlen(text);
    if (len >= sizeof e->message) {
        len = sizeof e->message - 1;
        while (len && text[len] != '\n')
            len--;
        if (!len)
            len = sizeof e->message - 1;
    }
    while (len && text[len - 1] == '\n')
        len--;
    gls_api_fail(e, "%.*s", (int)len, text);
}

int glscene_compile(const char *scene_path, const char *const *roots, size_t nroots, const char *out_bundle,
                    glscene_error *e)
{
    if (!scene_path || !out_bundle || (nroots && !roots))
        return gls_api_fail(e, "glscene_compile: a NULL scene, roots or output path");
    char *diag = NULL;
    size_t dlen = 0;
    FILE *d = open_memstream(&diag, &dlen);
    if (!d)
        return gls_api_fail(e, "out of memory");
    gls_compiler *c = gls_compiler_new(d);
    int rc = c ? 0 : -1;
    for (size_t i = 0; i < nroots && rc == 0; i++)
        rc = gls_compiler_add_root(c, roots[i]);
    if (rc == 0)
        rc = gls_compiler_add_env_roots(c);
    gls_bundle *b = NULL;
    if (rc == 0)
        rc = gls_compile_top(c, scene_path, &b);
    fclose(d);
    if (rc) {
        if (!c || !diag || !diag[0])
            gls_api_fail(e, "%s: the compiler failed and said nothing (out of memory?)", scene_path);
        else
            diagnostics_to_error(diag, e);
    } else {
        uint8_t *bytes;
        size_t len;
        gls_error err;
        if (gls_bundle_write(b, &bytes, &len, &err)) {
            rc = gls_api_fail(e, "%s", err.msg);
        } else {
            if (gls_mkdir_parents(out_bundle))
                rc = gls_api_fail(e, "cannot create the directory of %s: %s", out_bundle, strerror(errno));
            else if (gls_write_file_atomic(out_bundle, bytes, len))
                rc = gls_api_fail(e, "cannot write %s: %s", out_bundle, gls_write_error(out_bundle, errno));
            free(bytes);
        }
    }
    free(diag);
    gls_bundle_free(b);
    gls_compiler_free(c);
    return rc ? -1 : 0;
}
