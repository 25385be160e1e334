/* --progress json (runtime/write/progress_json.c): the exact lines for given
 * times, one whole line per call. */
#include <stdlib.h>
#include "check.h"
#include "progress_json.h"

static void test_lines(void)
{
    char *s = NULL;
    size_t len;
    FILE *f = open_memstream(&s, &len);
    gls_progress_json p = {f, 0, 4, 2, 1, 10.0};
    gls_progress_json_frame(&p, 7, "left", 10.5);
    /* a name that needs escaping stays one JSON string */
    gls_progress_json_frame(&p, 7, "r\"ig\\ht\n", 11.0);
    gls_progress_json_end(&p, 1, 12.0);
    gls_progress_json_end(&p, 0, 12.0);
    fclose(f);
    CHECK_STR(s, "{\"event\": \"frame\", \"frame\": 7, \"camera\": \"left\", \"done\": 1, \"total\": 4, "
                 "\"elapsed_s\": 0.500, \"rate_fps\": 2.000, \"eta_s\": 1.500}\n"
                 "{\"event\": \"frame\", \"frame\": 7, \"camera\": \"r\\\"ig\\\\ht\\u000a\", \"done\": 2, "
                 "\"total\": 4, \"elapsed_s\": 1.000, \"rate_fps\": 2.000, \"eta_s\": 1.000}\n"
                 "{\"event\": \"end\", \"status\": \"ok\", \"done\": 2, \"total\": 4, \"frames\": 1, "
                 "\"skipped\": 1, \"elapsed_s\": 2.000, \"rate_fps\": 1.000}\n"
                 "{\"event\": \"end\", \"status\": \"error\", \"done\": 2, \"total\": 4, \"frames\": 1, "
                 "\"skipped\": 1, \"elapsed_s\": 2.000, \"rate_fps\": 1.000}\n");
    free(s);
    /* no FILE: nothing, and nothing counted */
    gls_progress_json q = {NULL, 0, 4, 1, 0, 0};
    gls_progress_json_frame(&q, 0, "x", 1);
    CHECK(q.done == 0);
}

int main(void)
{
    RUN(test_lines);
    CHECK_EXIT();
}
