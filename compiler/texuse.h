/* Does a texture(...) statement ever texture anything?  Under texture mode
 * `color` (the initial mode) a selected texture is not applied, and the
 * player draws the primitive in plain colour without a word.  This tracks,
 * within one file, which texture(...) statement selected the current
 * texture and what the texture mode is, through push and pop, and warns
 * about a selection that primitives were drawn with only in mode color.
 *
 * A file starts with the mode its caller had.  For the top object that is
 * color; for a callee it is unknown, so drawing there counts as a use (no
 * warning); a call counts as a use too (the callee may set a mode and draw). */
#ifndef GLS_TEXUSE_H
#define GLS_TEXUSE_H
#include "bundle.h"
#include "diag.h"

enum { TEXUSE_INHERITED, TEXUSE_COLOR, TEXUSE_TEXTURED };

typedef struct {
    int mode;            /* TEXUSE_*                                          */
    unsigned color_line; /* the line of texmode(color), when mode is COLOR    */
    long sel;            /* index of the selecting statement, -1: none or the
                            caller's                                          */
} gls_texuse_state;

typedef struct {
    gls_loc loc;         /* the texture(...) statement                        */
    char *name;          /* the texture's name                                */
    unsigned color_line; /* drawn in mode color: texmode(color)'s line, or 0
                            for the initial mode; UINT_MAX: never drawn so    */
    int used;            /* drawn in a textured (or unknown) mode, or passed
                            to a call                                         */
} gls_texsel;

typedef struct {
    int top;                                     /* the file is the top object */
    gls_texuse_state cur;
    gls_texuse_state saved[GLS_MAX_PUSH_DEPTH];
    gls_texsel *sel;
    size_t nsel, cap;
} gls_texuse;

void gls_texuse_init(gls_texuse *t, int top);
/* texture("name") at loc (name without quotes, n bytes); -1 out of memory */
int gls_texuse_select(gls_texuse *t, gls_loc loc, const char *name, size_t n);
void gls_texuse_deselect(gls_texuse *t);
void gls_texuse_mode(gls_texuse *t, int textured, unsigned line);
/* push saves into slot depth (before it grows), pop restores from it */
void gls_texuse_push(gls_texuse *t, unsigned depth);
void gls_texuse_pop(gls_texuse *t, unsigned depth);
void gls_texuse_call(gls_texuse *t);
void gls_texuse_draw(gls_texuse *t);
/* Warn about every selection never applied; free everything. */
void gls_texuse_finish(gls_texuse *t, gls_diag *d);
#endif
