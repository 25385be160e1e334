/* The compiler's state while it finds, compiles and links objects, shared
 * by the files of the linker: roots.c (search roots), resolve.c (finding
 * objects and textures by name), import.c (objects taken from a bundle),
 * callgraph.c (the depth-first walk over calls), assemble.c (the bundle),
 * compile_top.c and compile_lib.c (the two modes), compiler.c (the
 * compiler's lifetime).  The public interface is compile.h. */
#ifndef GLS_LINKER_H
#define GLS_LINKER_H
#include "compile.h"
#include "strmap.h"
#include "unit.h"

typedef struct {
    char *path;
    gls_bundle *lib;      /* non-NULL for a bundle root */
} gls_root;

typedef struct {
    char *name;
    gls_texture tex;      /* tex.name is set at assembly */
    int ok;
} tex_entry;

/* What a name stands for through the roots (template.c): a .scene file,
 * compiled with its parameters' defaults when it is found (base), or an
 * entry of a bundle root, an object (base, imported) and, when it has
 * parameters, its template.  A name with parameters makes one object per
 * set of values (specialisations); base is the one with the defaults. */
typedef struct gls_tpl {
    char *name;
    unsigned nparams;
    char *pnames[GLS_MAX_PARAMS];
    double defaults[GLS_MAX_PARAMS];
    gls_unit *base;           /* the object with the defaults, once made   */
    gls_source src;           /* the text (borrowed from base, or from the
                                 bundle root's template)                   */
    uint32_t src_file;
    gls_tree tree;            /* parsed once, to run for other values      */
    int have_tree;
    const gls_bundle *lib;    /* a bundle root's entry                     */
    uint32_t lib_template;    /* its template, or GLS_NONE                 */
    int on_stack;             /* objects of it on the call path: calling it
                                 again is a cycle, whatever the values     */
    int in_bundle;            /* assemble.c                                 */
} gls_tpl;

struct gls_compiler {
    gls_diag diag;
    gls_root *roots;
    size_t nroots, rootscap;
    gls_strmap units;        /* name (with values) -> gls_unit*             */
    gls_strmap templates;    /* name -> gls_tpl*                            */
    gls_tpl **alltpl;        /* every template, for freeing                  */
    size_t nalltpl, alltplcap;
    uint64_t unrolled;       /* statements run in loops, all objects        */
    gls_strmap missing;      /* names already reported unknown -> (void*)1 */
    gls_strmap textures;     /* name -> tex_entry*                          */
    gls_unit **all;          /* every unit, for freeing                      */
    size_t nall, allcap;
    tex_entry **alltex;
    size_t nalltex, alltexcap;
    char **sources;
    uint32_t nsources;
    size_t sourcescap;
    gls_unit **stack;        /* DFS path, for cycle messages                */
    size_t depth, stackcap;
    const char *top_name;    /* the top object's name while it is loaded    */
    const char *build_dir;   /* where the build generates the scene library's
                                textures (hint in "unknown texture"), or NULL */
};

/* Errors with no source position. */
#define GLS_NOLOC ((gls_loc){NULL, 0, 0})

/* compiler.c: append p to the growing array *arr of *n (capacity *cap). */
int gls_push_ptr(void ***arr, size_t *n, size_t *cap, void *p);

/* roots.c */
char *gls_normalise_path(const char *path);
/* "a.b.C" + root + ext -> "root/a/b/C.ext" */
char *gls_name_to_path(const char *root, const char *name, const char *ext);
/* "R1, R2, ..." for "searched:" messages */
void gls_list_roots(const gls_compiler *c, char *buf, size_t n);
/* The current directory, if no root was given. */
void gls_default_root(gls_compiler *c);
/* Insert the directory root first (--lib); -1 when out of memory. */
int gls_add_root_first(gls_compiler *c, const char *dir);

/* resolve.c */
/* the image extensions tried, in this order (spec/language.md 2.1) */
#define GLS_NTEX_EXTS 5
extern const char *const gls_tex_exts[GLS_NTEX_EXTS];
int gls_valid_object_name(const char *s);
uint32_t gls_add_source(gls_compiler *c, const char *path);
int gls_register_unit(gls_compiler *c, gls_unit *u);
/* What name stands for, found through the roots (a .scene file is
 * compiled with its defaults then); NULL after reporting it unknown. */
gls_tpl *gls_get_tpl(gls_compiler *c, const char *name, gls_loc loc);
tex_entry *gls_get_texture(gls_compiler *c, const char *name, gls_loc loc);

/* template.c */
/* The .scene file path as the object name, compiled with its defaults
 * (its tree kept if it has parameters) and registered. */
gls_tpl *gls_tpl_from_file(gls_compiler *c, const char *name, const char *path, gls_loc loc);
/* The entry name of bundle root b (object oi and/or template ti), its
 * object imported; registered. */
gls_tpl *gls_tpl_from_lib(gls_compiler *c, const gls_bundle *b, const char *name, uint32_t oi, uint32_t ti,
                          gls_loc loc);
void gls_tpl_free(gls_tpl *t);
/* Match a call's parameter values to t's parameters (errors at the
 * values, "unknown parameter"): the values of every parameter in values[],
 * 0; or -1. */
int gls_tpl_bind(gls_compiler *c, const gls_tpl *t, const gls_named *args, unsigned nargs, double *values);
/* The name of t's object for values (t's name when they are the
 * defaults), into b; 0, or -1 after an error at loc. */
int gls_tpl_object_name(gls_compiler *c, const gls_tpl *t, const double *values, gls_buf *b, gls_loc loc);
/* The object name stands for with a call's parameter values: made once
 * per set of values.  NULL after reporting why. */
gls_unit *gls_get_unit(gls_compiler *c, const char *name, const gls_named *args, unsigned nargs, gls_loc loc);

/* import.c */
gls_unit *gls_unit_from_lib(gls_compiler *c, const gls_bundle *b, uint32_t oi, gls_loc loc);

/* callgraph.c */
void gls_visit(gls_compiler *c, gls_unit *u);

/* assemble.c */
gls_bundle *gls_assemble(gls_compiler *c, const gls_unit *top, int all_textures);

/* instnames.c: a scene's instance names each given once and reached once
 * from its top object; 0, or -1 after reporting why not. */
int gls_check_instance_names(gls_compiler *c, const gls_bundle *b);
#endif
