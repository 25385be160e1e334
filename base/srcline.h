/* The source excerpt under a diagnostic: the offending line and a caret
 * under the column.  The one printer of every text parser's errors: the
 * scene compiler's (compiler/diag.c), camera files, road descriptions. */
#ifndef GLS_SRCLINE_H
#define GLS_SRCLINE_H
#include <stddef.h>
#include "buf.h"

/* How the excerpt shows a line.  The compiler shows the whole line and
 * reports errors after a NUL byte in it, so its caret may go past a NUL
 * (the text shown stops there: a message is a C string).  Text inputs
 * (camera files, road descriptions) refuse NUL bytes, so there a line
 * ends at one; and a line over 200 bytes is shown as a 160-byte window
 * around the column, "..." marking the cut ends. */
typedef enum { GLS_EXCERPT_WHOLE_LINE, GLS_EXCERPT_WINDOW } gls_excerpt_style;

/* Append "<line LINE of text>\n<spaces>^" to b, the caret under 1-based
 * column COL (tabs kept so that it lines up).  Returns 0, or -1 if there
 * is no such line (nothing appended) or no memory. */
int gls_excerpt(gls_buf *b, const char *text, size_t len, unsigned line, unsigned col, gls_excerpt_style style);

/* Append "\n" and the GLS_EXCERPT_WINDOW excerpt to the NUL-terminated
 * string in buf (capacity cap).  Appends nothing if it does not fit. */
void gls_append_source_line(char *buf, size_t cap, const char *text, size_t len, unsigned line, unsigned col);

/* The located error of a text input, into err: "FILE:LINE:COL: error: "
 * and the formatted message, then the excerpt (gls_append_source_line). */
void gls_text_error(char *err, size_t errlen, const char *text, size_t len, const char *file, unsigned line,
                    unsigned col, const char *fmt, ...) __attribute__((format(printf, 8, 9)));
#endif
