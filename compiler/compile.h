/* The compiler's public interface, used by glsc and by tests. */
#ifndef GLS_COMPILE_H
#define GLS_COMPILE_H
#include <stdio.h>
#include "bundle.h"

typedef struct gls_compiler gls_compiler;

/* Diagnostics are printed to diag_out. */
gls_compiler *gls_compiler_new(FILE *diag_out);
void gls_compiler_free(gls_compiler *c);

/* Add a search root: a directory, or a bundle file (LIB.glsb).  Roots are
 * searched in the order added.  Returns 0, or -1 after printing why. */
int gls_compiler_add_root(gls_compiler *c, const char *path);
/* Add the colon-separated roots of the environment variable GLSCENE_PATH. */
int gls_compiler_add_env_roots(gls_compiler *c);
/* The build directory (glsc: the directory it was run from, build/).  The
 * build generates the scene library's textures in DIR/textures; an unknown
 * texture found there gets "; the build generates it in DIR/textures: add
 * -I DIR/textures" in its message (spec/language.md 2.1).  dir is
 * borrowed. */
void gls_compiler_set_build_dir(gls_compiler *c, const char *dir);
/* Where the build generates the scene library's textures (glsc: the
 * directory "textures" beside itself).  An unknown texture found there gets
 * "; the build generates it in DIR: add -I DIR" in its message.  dir is
 * borrowed. */
void gls_compiler_set_generated_textures(gls_compiler *c, const char *dir);

/* Compile the scene whose top-level object is `top` (a .scene path or a
 * dotted name) into a bundle holding exactly what it reaches.  If no root
 * was added, the current directory is the root.  Returns 0 and *out, or -1
 * after printing the errors. */
int gls_compile_top(gls_compiler *c, const char *top, gls_bundle **out);

/* Compile every object and texture under the directory root into a library
 * bundle (no top level). */
int gls_compile_lib(gls_compiler *c, const char *root, gls_bundle **out);

/* Number of errors reported so far. */
unsigned gls_compiler_errors(const gls_compiler *c);

/* Decode an image file into a binary-alpha RGBA texture.  On failure returns
 * -1 with a message in why. */
int gls_texture_decode(const char *path, gls_texture *out, char *why, size_t whylen);
/* Check an image's header without decoding it: known format, size within
 * the GL limit and GLS_MAX_TEXELS; *w, *h set. */
int gls_texture_probe(const unsigned char *data, size_t len, const char *path, int *w, int *h, char *why,
                      size_t whylen);
/* The same from memory; path is for messages. */
int gls_texture_decode_memory(const unsigned char *data, size_t len, const char *path, gls_texture *out, char *why,
                              size_t whylen);
#endif
