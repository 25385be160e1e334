/* A compilation unit: one object, compiled from one .scene file (or
 * imported from a library bundle).  Its bytecode uses unit-local indices
 * that the linker relocates when it assembles the bundle (assemble.c), by
 * operand kind (format/opcodes.h):
 *   OBJECT (call)                -> index into unit->refs (resolved by name)
 *   TEXTURE                      -> index into unit->texrefs
 *   FIRST_POS, FIRST_COL, FIRST_TC -> indices into the unit's vertex arrays
 *   INSTNAME (calln)             -> index into unit->instnames
 *   MARKNAME (mark)              -> index into unit->marknames
 *   CLASSNAME (class)            -> index into unit->classnames
 */
#ifndef GLS_UNIT_H
#define GLS_UNIT_H
#include "ast.h"
#include "bundle.h"
#include "diag.h"

/* A parameter value: given by a call (name and loc point at "NAME = ..."
 * in the caller), or bound for a run of a parameterised file. */
typedef struct {
    char *name;
    double value;
    gls_loc loc;
} gls_named;

typedef struct {
    char *name;        /* dotted name being referred to (an object's name
                          without parameter values)                  */
    gls_loc loc;       /* where (the string argument)                */
    gls_named *args;   /* call: the parameter values given, as written */
    unsigned nargs;
    struct gls_unit *target; /* call: the object linked (callgraph.c)  */
} gls_ref;

typedef struct {
    double v[16];
} gls_numargs;

struct gls_tpl;

typedef struct gls_unit {
    char *name;              /* with parameter values, when specialised   */
    gls_source src;          /* the text compiled (compiled units only)    */
    int src_borrowed;        /* the text belongs to the template          */
    struct gls_tpl *tpl;     /* the file or bundle entry it comes from     */
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
    gls_ref *instnames;      /* instance names of calls ("car1"), with
                                where each is written, in CALLN order     */
    uint32_t ninstnames;
    size_t instnames_cap;
    gls_ref *marknames;      /* landmark names of marks, with where each
                                is written, in MARK order; unique         */
    uint32_t nmarknames;
    size_t marknames_cap;
    gls_ref *classnames;     /* the class the object's `class` gives, with
                                where it is written: at most one          */
    uint32_t nclassnames;
    size_t classnames_cap;
    gls_vec4 *pos; uint32_t npos; size_t pos_cap;
    gls_rgba *col; uint32_t ncol; size_t col_cap;
    gls_st *tc;    uint32_t ntc;  size_t tc_cap;
    gls_nrm *nrm;  uint32_t nnrm; size_t nrm_cap;
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

/* A parsed file kept to be run again with other parameter values
 * (template.c): its top-level statements in the arena they live in, and
 * its parameters with their defaults. */
typedef struct {
    gls_arena arena;
    gls_stmt *top;
    int syntax_errors;
    unsigned end_line;              /* the line of the file's end (END)   */
    unsigned nparams;
    gls_tok pnames[GLS_MAX_PARAMS]; /* point into the source text */
    double defaults[GLS_MAX_PARAMS];
} gls_tree;

/* Parse and compile one .scene source into u (u->name and u->src set by
 * the caller), its parameters at their defaults.  Errors go to d.  Returns
 * 0 if no error was reported. */
int gls_compile_source(gls_unit *u, gls_diag *d);
/* The same, keeping the tree in *keep when the file declares parameters
 * (keep->nparams > 0; free it with gls_tree_free), and counting loop
 * statements in *total (the compile's budget; may be NULL). */
int gls_compile_source_keep(gls_unit *u, gls_diag *d, gls_tree *keep, uint64_t *total);
/* Parse src only, keeping the tree (a parameterised object from a bundle;
 * nothing is run but the parameters' defaults).  0 if no error. */
int gls_parse_tree(const gls_source *src, gls_diag *d, gls_tree *out);
/* Run a kept tree into u (u->src set), with the values of every parameter
 * in binding.  0 if no error was reported. */
int gls_run_tree(gls_unit *u, gls_diag *d, const gls_tree *t, const gls_named *binding, unsigned nbinding,
                 uint64_t *total);
void gls_tree_free(gls_tree *t);
#endif
