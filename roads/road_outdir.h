/* glsroad's output directory, written as a whole (spec/road.md, "Outputs"):
 * the set of files goes into a temporary sibling directory, which then
 * takes DIR's place in one rename, so DIR holds either the old set or the
 * new one, never a mix, whatever fails part way. */
#ifndef GLS_ROAD_OUTDIR_H
#define GLS_ROAD_OUTDIR_H
#include <stddef.h>

typedef struct {
    const char *name; /* relative to DIR; at most one directory level ("roadobj/Tree.scene") */
    const char *data;
    size_t len;
} road_out_file;

/* May DIR be (re)written with these names?  Yes if it does not exist, is
 * an empty directory, or holds nothing but files of those names (a
 * previous output).  0, or -1 with "glsroad: error: ..." in err. */
int road_outdir_check(const char *dir, const road_out_file *files, int n, char *err, size_t errlen);

/* Write the files as DIR's whole content, replacing a previous output.
 * 0, or -1 with the error in err and DIR as it was. */
int road_outdir_write(const char *dir, const road_out_file *files, int n, char *err, size_t errlen);
#endif
