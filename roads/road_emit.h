/* What glsroad's text outputs share (road_text.c) and the tessellation
 * with a limit (road_stations.c).  Internal to roads/: the scene
 * (road_scene.c), its objects (road_objects.c), the lane polylines
 * (road_lanes.c) and the motion outputs (road_motion.c). */
#ifndef GLS_ROAD_EMIT_H
#define GLS_ROAD_EMIT_H
#include <stdio.h>
#include "road.h"

/* road_stations, giving up with -2 beyond max stations. */
long road_stations_upto(const road_geo *g, double u0, double u1, const road_edge *edges, int nedges, double **st,
                        long max);

/* The tessellation that the tolerance and max_segment ask for needs more
   than ROAD_MAX_VERTICES for what ("the lane polylines (lanes.txt)"): the
   error, at the key that sets it.  Returns -1. */
int road_too_fine(const road_desc *d, char *err, size_t errlen, const char *what);

/* "vert(x, y, z);", numbers shortest round-trip. */
void road_vert(FILE *f, rv3 P);

/* A stream writing into b (emptied first); NULL with "FILE: error: out
   of memory" in err. */
FILE *road_buf_open(road_buf *b, const char *file, char *err, size_t errlen);
/* Close a stream of road_buf_open: 0, or -1 with the error in err (b's
   text stays the caller's to free). */
int road_buf_close(FILE *f, road_buf *b, const char *file, char *err, size_t errlen);

/* roadobj/Tree.scene and roadobj/Car.scene, glsroad's own objects: 0, or
   -1 with the error in err. */
int road_emit_objects(road_buf *tree, road_buf *car, const char *file, char *err, size_t errlen);
#endif
