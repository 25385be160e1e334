/* The source excerpt under a diagnostic: the offending line and a caret
 * under the column, shared by every text parser's error messages (camera
 * files, road descriptions; the scene compiler prints the same form). */
#ifndef GLS_SRCLINE_H
#define GLS_SRCLINE_H
#include <stddef.h>

/* Append "\n<line LINE of text>\n<spaces>^" to the NUL-terminated string
 * in buf (capacity cap), the caret under 1-based column COL (tabs kept so
 * it lines up).  A line over 200 bytes is shown as a 160-byte window
 * around the column, "..." marking the cut ends.  Appends nothing if it
 * does not fit. */
void gls_append_source_line(char *buf, size_t cap, const char *text, size_t len, unsigned line, unsigned col);
#endif
