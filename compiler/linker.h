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

struct gls_compiler {
    gls_diag diag;
    gls_root *roots;
    size_t nroots, rootscap;
    gls_strmap units;        /* name -> gls_unit*; NULL-valued never stored */
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
    const char *build_dir;   /* where the build generates the scene library
                                (hint in "unknown" messages), or NULL      */
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
gls_unit *gls_unit_from_file(gls_compiler *c, const char *name, const char *path, gls_loc loc);
int gls_register_unit(gls_compiler *c, gls_unit *u);
gls_unit *gls_get_unit(gls_compiler *c, const char *name, gls_loc loc);
tex_entry *gls_get_texture(gls_compiler *c, const char *name, gls_loc loc);

/* import.c */
gls_unit *gls_unit_from_lib(gls_compiler *c, const gls_bundle *b, uint32_t oi, gls_loc loc);

/* callgraph.c */
void gls_visit(gls_compiler *c, gls_unit *u);

/* assemble.c */
gls_bundle *gls_assemble(gls_compiler *c, const gls_unit *top, int all_textures);
#endif
