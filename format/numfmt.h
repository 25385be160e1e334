/* Shortest decimal text that reads back as exactly the same number. */
#ifndef GLS_NUMFMT_H
#define GLS_NUMFMT_H
#include <stddef.h>
void gls_fmt_double(char *buf, size_t n, double v);
void gls_fmt_float(char *buf, size_t n, float v);
#endif
