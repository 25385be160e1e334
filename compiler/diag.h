/* Diagnostics: "file:line:col: error: message", then the source line and a
 * caret under the column.  Counts errors and stops at a limit. */
#ifndef GLS_DIAG_H
#define GLS_DIAG_H
#include <stddef.h>
#include <stdio.h>

#define GLS_MAX_ERRORS 20

typedef struct {
    const char *path;   /* file name as given                       */
    const char *text;   /* whole source, NUL-terminated              */
    size_t len;
    size_t mapped;      /* text is an mmap of this length, or 0 if malloc'd */
} gls_source;

typedef struct {
    const gls_source *src;   /* NULL for errors with no source position */
    unsigned line, col;      /* 1-based                                  */
} gls_loc;

typedef struct {
    FILE *out;
    unsigned errors;   /* every error, also those not printed again      */
    unsigned printed;  /* errors printed: GLS_MAX_ERRORS counts these    */
    unsigned warnings; /* they do not stop the compile or change its status */
    int stopped;   /* the error limit was reached: callers stop */
    /* dedupe: print a diagnostic only once however often it is found (a
       parameterised object is run once per set of values, and the same
       mistake in it would be found each time); seen holds what was
       printed.  Free with gls_diag_free. */
    int dedupe;
    void *seen;
    /* a specialised object being made: each diagnostic gets a note
       "while making NAME for this call" at the call */
    const char *making;
    gls_loc making_at;
} gls_diag;

void gls_error_at(gls_diag *d, gls_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void gls_note_at(gls_diag *d, gls_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* "file:line:col: warning: message", source line and caret */
void gls_warning_at(gls_diag *d, gls_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

void gls_diag_free(gls_diag *d);

#include "suggest.h" /* gls_suggest for "did you mean" */
#endif
