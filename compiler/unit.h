/* A compilation unit: one object, compiled from one .scene file (or
 * imported from a library bundle).  Its bytecode uses unit-local indices
 * that the linker relocates when it assembles the bundle (assemble.c), by
 * operand kind (format/opcodes.h):
 *   OBJECT (call)                -> index into unit->refs (resolved by name)
 *   TEXTURE                      -> index into unit->texrefs
 *   FIRST_POS, FIRST_COL, FIRST_TC -> indices into the unit's vertex arrays
 */
#ifndef GLS_UNIT_H
#define GLS_UNIT_H
#include "bundle.h"
#include "diag.h"

typedef struct {
    char *name;        /* dotted name being referred to              */
    gls_loc loc;       /* where (the string argument)                */
} gls_ref;

typedef struct {
    double v[16];
} gls_numargs;

typedef struct gls_unit {
    char *name;
    gls_source src;          /* owned text (compiled units only)          */
    uint32_t src_file;       /* index in the compiler's source-name list  */
    gls_buf code;
    uint32_t ninsn;
    gls_srcloc *lines;       /* per instruction                           */
    size_t lines_cap;
    gls_ref *refs;           /* call targets, in CALL operand order        */
    uint32_t nrefs;
    size_t refs_cap;
    gls_ref *texrefs;        /* textures named by texture("...")          */
    uint32_t ntexrefs;
    size_t texrefs_cap;
    gls_vec4 *pos; uint32_t npos; size_t pos_cap;
    gls_rgba *col; uint32_t ncol; size_t col_cap;
    gls_st *tc;    uint32_t ntc;  size_t tc_cap;
    int is_top;              /* compiled as the top object: its initial
                                texture mode is known to be color          */
    /* linker state */
    int state;               /* 0 unvisited, 1 on the DFS stack, 2 done   */
    uint32_t height;         /* call edges in the longest chain below it  */
    uint32_t final_index;
} gls_unit;

void gls_unit_free(gls_unit *u);

/* Append instruction in (with local operands) and its source line. */
int gls_unit_emit(gls_unit *u, const gls_insn *in, uint32_t line);
/* Add a reference (call or texture); returns its index or GLS_NONE. */
uint32_t gls_unit_add_ref(gls_ref **arr, uint32_t *n, size_t *cap, const char *name, size_t len, gls_loc loc);

/* Parse and compile one .scene source into u (u->name and u->src set by
 * the caller).  Errors go to d.  Returns 0 if no error was reported. */
int gls_compile_source(gls_unit *u, gls_diag *d);
#endif
