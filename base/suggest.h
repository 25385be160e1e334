/* "Did you mean": the closest known word to a misspelt one, shared by every
 * parser in the tree (scene compiler, camera files, road descriptions). */
#ifndef GLS_SUGGEST_H
#define GLS_SUGGEST_H
#include <stddef.h>

/* Optimal-string-alignment distance between a[0..alen) and b:
 * insertions, deletions, substitutions and swaps of two neighbouring
 * letters each cost 1 ("trnas" is 1 from "trans"); letters compare without
 * case ("r" matches "R").  Words over 64 bytes are 1000 apart. */
unsigned gls_edit_distance(const char *a, size_t alen, const char *b);

/* The candidate closest to word[0..len), if it is close enough to be a
 * likely typo (distance 1 for words of up to 3 letters, else at most 2);
 * NULL otherwise.  cands has n entries, or ends with NULL when n is
 * (size_t)-1. */
const char *gls_suggest(const char *word, size_t len, const char *const *cands, size_t n);

/* A name people bring from elsewhere (OpenGL, other scene languages) and
 * the word it stands for here: {"translate", "trans"}.  Written in lower
 * case. */
typedef struct {
    const char *alias, *word;
} gls_alias;

/* As gls_suggest, but also knowing aliases: a word that is an alias
 * (without regard to case) suggests the alias's word however far apart they
 * are, and a typo of an alias suggests it too.  OpenGL's spelling of a
 * candidate or an alias counts as the name itself: "gl", the name, then a
 * type suffix such as 3f, d, fv or 4ub (glTranslatef -> trans, glScaled ->
 * scale, glVertex3f -> vert), or "GL_" and the name (GL_TRIANGLE_STRIP ->
 * tstrip).  Only aliases whose word is one of the
 * candidates apply, so one table serves several candidate lists. */
const char *gls_suggest_alias(const char *word, size_t len, const char *const *cands, size_t n,
                              const gls_alias *aliases, size_t naliases);
#endif
