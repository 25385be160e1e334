/* glsdis: print a bundle as a stable, diffable text dump. */
#include <stdio.h>
#include <string.h>
#include "disasm.h"
#include "stdout_check.h"
#include "usage.h"

#define USAGE \
    "usage: glsdis [--source] BUNDLE.glsb\n" \
    "       glsdis --help | --version\n" \
    "\n" \
    "Print the bundle as text: header and features, textures (size and content\n" \
    "hash), then each object's instructions and vertices.  --source appends the\n" \
    "file:line each instruction came from.\n" \
    "Exit status: 0 success, 1 unreadable or invalid bundle, 2 usage error.\n"
#define usage_error(...) gls_usage_error("glsdis", "\n" USAGE, __VA_ARGS__)

int main(int argc, char **argv)
{
    gls_check_stdout_at_exit("glsdis");
    int with_source = 0;
    const char *path = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--source") == 0)
            with_source = 1;
        else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            gls_stdout_text(USAGE);
            return 0;
        } else if (strcmp(argv[i], "--version") == 0) {
            return gls_version("glsdis");
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return usage_error("unknown option %s", argv[i]);
        } else if (path) {
            return usage_error("%s", "more than one bundle given");
        } else if (!argv[i][0]) { /* names no file (spec/exit_status.md) */
            return usage_error("%s", "an empty bundle name");
        } else
            path = argv[i];
    }
    if (!path) {
        return usage_error("%s", "no bundle given");
    }
    gls_error err;
    gls_bundle *b = gls_bundle_read_file(path, &err);
    if (!b) {
        fprintf(stderr, "glsdis: error: %s\n", err.msg);
        return 1;
    }
    gls_disassemble(b, stdout, with_source);
    gls_bundle_free(b);
    return 0; /* a failed write is reported at exit (stdout_check.h) */
}
