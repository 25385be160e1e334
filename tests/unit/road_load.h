/* Shared by the road unit tests: parse a description and build its
 * geometry, printing the error and returning -1 on failure. */
#ifndef GLS_TEST_ROAD_LOAD_H
#define GLS_TEST_ROAD_LOAD_H
#include <stdio.h>
#include <string.h>
#include "road.h"

static int load(const char *text, road_desc *d, road_geo *g)
{
    char err[1024];
    if (road_parse(text, strlen(text), "test.road", d, err, sizeof err)) {
        printf("  %s\n", err);
        return -1;
    }
    if (road_geo_init(g, d, err, sizeof err)) {
        printf("  %s\n", err);
        road_desc_free(d);
        return -1;
    }
    return 0;
}
#endif
