/* The names of specialised objects (spec/bundle.md 2): the object's name,
 * then its parameter values in declaration order, each in its shortest
 * round-trip form (base/numfmt.h): "road.markings.Dash(length=3,width=0.15)".
 * One set of values has one spelling, so equal values share one object.
 * The compiler writes these names, the validator checks them, and the
 * compiler reads them back when it imports an object from a bundle. */
#ifndef GLS_SPECNAME_H
#define GLS_SPECNAME_H
#include <stddef.h>
#include "buf.h"

typedef struct {
    const char *name; /* points into the name read */
    size_t len;
    double value;
} gls_specarg;

/* Append base(names[0]=values[0],...,names[n-1]=values[n-1]) and a NUL to
 * b (the NUL not counted in b->len).  0, or -1 when out of memory. */
int gls_specname_write(gls_buf *b, const char *base, const char *const *names, const double *values, unsigned n);

/* Split s: the length of its base, with its values in args[0..*n) (at
 * most max of them); for a name without "(", strlen(s) and *n = 0.  -1 if
 * s has a "(" but is not exactly base(NAME=VALUE,...) with identifiers
 * for names and finite values in their shortest round-trip form. */
long gls_specname_parse(const char *s, gls_specarg *args, unsigned max, unsigned *n);
#endif
