/* glsplay_bands_whole ARGS...: glsplay's run of ARGS (glsplay's arguments,
 * through the library's parser, glscene_play_arg) with every band of rows
 * of a rolling shutter drawing and reading back the whole image
 * (gls_play_opts' bands_whole; gls_bands in runtime/effects/exposure.h),
 * as before the bands' rows were narrowed.  For tests/e2e/rolling_bands.sh,
 * which compares its files byte for byte with glsplay's.  A test's
 * choice, so it is this program of the tests' and not an option of
 * glsplay, nor a variable of the environment the player would read.
 * Exit status as glsplay's; no --help. */
#include <stdio.h>
#include "glscene.h"
#include "glscene_internal.h"

int main(int argc, char **argv)
{
    glscene_play *r = glscene_play_new();
    if (!r)
        return 1;
    glscene_error e;
    int rc = 0;
    for (int i = 1; i < argc && !rc;) {
        int k = glscene_play_arg(r, argv[i], i + 1 < argc ? argv[i + 1] : NULL, &e);
        if (k < 0)
            fprintf(stderr, "glsplay_bands_whole: error: %s\n", glscene_play_message(r)), rc = 2;
        else
            i += k;
    }
    if (!rc && glscene_play_check(r, &e))
        fprintf(stderr, "glsplay_bands_whole: error: %s\n", glscene_play_message(r)), rc = 2;
    if (!rc) {
        gls_api_play_opts(r)->bands_whole = 1;
        rc = glscene_play_run(r, stdout, stderr);
    }
    glscene_play_free(r);
    return rc;
}
