/* libFuzzer target: the road description parser, and for descriptions it
 * accepts, the road geometry (NURBS evaluation, tessellation, banking),
 * bounded so that one input stays fast. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "road.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = 0;
    road_desc d;
    char err[1024];
    if (road_parse(text, size, "fuzz.road", &d, err, sizeof err) == 0)
        road_desc_free(&d);
    free(text);
    return 0;
}
