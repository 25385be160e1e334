/* A double-quoted string for YAML or JSON, appended to a gls_buf: the
 * calibration files (runtime/calib_write.c) and the --progress json lines
 * (runtime/progress_json.c) name cameras with it. */
#ifndef GLS_QUOTED_H
#define GLS_QUOTED_H
#include "buf.h"

/* '"' and '\' escaped, control bytes as \xNN (YAML) or \u00NN (json set);
 * other bytes as they are.  0, or -1 when out of memory. */
int gls_buf_quoted(gls_buf *b, const char *s, int json);
#endif
