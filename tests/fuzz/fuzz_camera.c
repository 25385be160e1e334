/* libFuzzer target: the camera file parser. */
#include <stdlib.h>
#include <string.h>
#include "camera.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    gls_camera c;
    char err[512];
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    gls_camera_parse(text, size, "fuzz.cam", GLS_POSE_UNDECLARED, NULL, &c, err, sizeof err);
    free(text);
    return 0;
}
