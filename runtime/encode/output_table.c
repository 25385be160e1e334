/* The output vocabulary as data (output_table.h): the rows of
 * GLS_OUTPUTS, and the words --outputs takes. */
#include <string.h>
#include "output_table.h"

const gls_output_kind gls_output_kinds[GLS_OUT_KINDS] = {
#define X(id, word, stem, ext, needs, with, listed, what, key) {GLS_OUT_##id, word, stem, ext, needs, with, listed, what, key},
    GLS_OUTPUTS(X)
#undef X
};

unsigned gls_output_word_bits(const char *word, size_t len)
{
    unsigned bits = 0;
    for (int k = 0; k < GLS_OUT_KINDS; k++) {
        const char *w = gls_output_kinds[k].word;
        if (w && strlen(w) == len && memcmp(w, word, len) == 0)
            bits |= gls_output_kinds[k].bit;
    }
    return gls_outputs_with(bits);
}

unsigned gls_outputs_with(unsigned bits)
{
    for (int k = 0; bits && k < GLS_OUT_KINDS; k++)
        if (gls_output_kinds[k].with & bits)
            bits |= gls_output_kinds[k].bit;
    return bits;
}

size_t gls_output_words(const char **words, size_t cap, int unlisted)
{
    size_t n = 0;
    for (int pass = 0; pass < 1 + (unlisted != 0); pass++)
        for (int k = 0; k < GLS_OUT_KINDS; k++) {
            const char *w = gls_output_kinds[k].word;
            if (!w || gls_output_kinds[k].listed != !pass || (n && strcmp(words[n - 1], w) == 0))
                continue;
            if (n < cap)
                words[n] = w;
            n++;
        }
    return n < cap ? n : cap;
}
