/* The player's frame progress line, its render-time estimate and the
 * duration and size formats they use (runtime/play/progress.c, units.c):
 * given numbers in, exact text out, no clock involved. */
#include <stdlib.h>
#include "check.h"
#include "progress.h"
#include "units.h"

/* What fn wrote to a FILE*, as a string (caller frees). */
#define CAPTURE(out, call)                                                            \
    do {                                                                              \
        size_t len_;                                                                  \
        FILE *f = open_memstream(&(out), &len_);                                      \
        call;                                                                         \
        fclose(f);                                                                    \
    } while (0)

static void test_durations(void)
{
    static const struct {
        double s;
        const char *text;
    } c[] = {{0.0004, "400 us"},   {0.0401, "40.1 ms"},      {0.25, "250 ms"},
             {1.25, "1.25 s"},     {42, "42 s"},             {185, "3 min 05 s"},
             {3599, "59 min 59 s"}, {25920, "7 h 12 min"},   {-1, "?"}};
    char buf[32];
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        gls_fmt_duration(buf, sizeof buf, c[i].s);
        CHECK_STR(buf, c[i].text);
    }
}

static void test_sizes(void)
{
    char buf[32];
    gls_fmt_bytes(buf, sizeof buf, 900);
    CHECK_STR(buf, "900 bytes");
    gls_fmt_bytes(buf, sizeof buf, 12288);
    CHECK_STR(buf, "12.0 KiB");
    gls_fmt_bytes(buf, sizeof buf, 512ull << 20);
    CHECK_STR(buf, "512 MiB");
    gls_fmt_bytes(buf, sizeof buf, 1152000000ull); /* a 12000x12000 framebuffer, 8 bytes a pixel */
    CHECK_STR(buf, "1.1 GiB");
}

static void test_frame_progress(void)
{
    char *s = NULL;
    /* 12 of 500 frames in 4 s: 3 frames/s, 488 left take 162.7 s */
    CAPTURE(s, gls_progress_frames(f, 12, 500, 4.0, 0));
    CHECK_STR(s, "\rglsplay: frame 12/500 (2%), 3.00 frames/s, 2 min 43 s left   ");
    free(s);
    CAPTURE(s, gls_progress_frames(f, 500, 500, 160.0, 1));
    CHECK_STR(s, "\rglsplay: 500 frames in 2 min 40 s, 3.12 frames/s          \n");
    free(s);
    CAPTURE(s, gls_progress_frames(f, 1, 1, 0.3, 1));
    CHECK_STR(s, "\rglsplay: 1 frame in 300 ms, 3.33 frames/s          \n");
    free(s);
}

static void test_estimate(void)
{
    /* 200 anti-aliasing passes in 2 s, 768 x 768 passes (one sample each)
     * for one camera frame: 5898 s */
    CHECK_NEAR(gls_estimate_total(2.0, 200, 589824, 1), 5898.24, 1e-9);
    char *s = NULL;
    int printed = 0;
    CAPTURE(s, printed = gls_estimate_report(f, 2.0, 200, 589824, 1));
    CHECK(printed == 1);
    CHECK_STR(s, "glsplay: note: estimated render time 1 h 38 min: 1 camera frame x 589824 anti-aliasing passes "
                 "x 10.0 ms (measured on the first 200 passes; --explain shows the plan)\n");
    free(s);
    /* whole camera frames: 2 in 0.6 s, 500 to render: 150 s */
    CAPTURE(s, printed = gls_estimate_report(f, 0.6, 2, 1, 500));
    CHECK(printed == 1);
    CHECK_STR(s, "glsplay: note: estimated render time 2 min 30 s: 500 camera frames x 300 ms (measured on the "
                 "first 2)\n");
    free(s);
    /* a minute or less: nothing (16 passes of 50 ms for 4 camera frames
     * is 3.2 s; 240 frames at 0.25 s is exactly 60 s) */
    CAPTURE(s, printed = gls_estimate_report(f, 0.5, 10, 16, 4));
    CHECK(printed == 0 && s[0] == 0);
    free(s);
    CAPTURE(s, printed = gls_estimate_report(f, 0.5, 2, 1, 240));
    CHECK(printed == 0 && s[0] == 0);
    free(s);
    CHECK(gls_estimate_total(1.0, 0, 10, 10) == 0); /* nothing measured yet */
}

int main(void)
{
    RUN(test_durations);
    RUN(test_sizes);
    RUN(test_frame_progress);
    RUN(test_estimate);
    CHECK_EXIT();
}
