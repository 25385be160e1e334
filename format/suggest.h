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
#endif
