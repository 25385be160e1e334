/* Shortest decimal text that reads back as exactly the same number, and
 * the matching reader of number tokens in text inputs. */
#ifndef GLS_NUMFMT_H
#define GLS_NUMFMT_H
#include <stddef.h>
void gls_fmt_double(char *buf, size_t n, double v);
void gls_fmt_float(char *buf, size_t n, float v);

/* Read a whole token as a finite double.  Returns NULL with *out set, or
 * what is wrong with the token, worded to follow it in a message
 * ("'1e-308' is too close to zero ..."): not a finite number, too large
 * for a double, or too close to zero (a nonzero magnitude below the
 * smallest normal double, which strtod can only approximate). */
const char *gls_parse_double(const char *tok, double *out);

/* The same, but accepting whatever strtod rounds to a finite number (a
 * magnitude that underflows to a subnormal or to zero included): NULL
 * with *out set, or "is not a finite number". */
const char *gls_parse_finite(const char *tok, double *out);
#endif
