/* An option's or key's value that must be one word of a fixed set (or a
 * comma-separated list of such words): finding it, and the one message
 * every tool gives when it is not one of them, naming the option, every
 * word it takes, what was given and the likely typo (suggest.h):
 *
 *   --pattern takes one of: lattice, grid, stratified (not 'gird'); did you mean 'grid'?
 *   --outputs takes a comma-separated list of: image, depth, ... (not 'dpeth'); did you mean 'depth'?
 *   --pattern needs one of: lattice, grid, stratified          (no value given)
 */
#ifndef GLS_CHOICE_H
#define GLS_CHOICE_H
#include <stddef.h>

/* The index of word[0..len) in words[0..n), or -1. */
int gls_choice_find(const char *word, size_t len, const char *const *words, size_t n);

/* The message above for what (such as "--pattern") into msg[0..msglen),
 * truncated if need be.  list: the value is a comma-separated list;
 * bad[0..badlen): the word not taken (in a list: the first one), NULL when
 * no value was given. */
void gls_choice_message(char *msg, size_t msglen, const char *what, int list, const char *bad, size_t badlen,
                        const char *const *words, size_t n);
#endif
