#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"

/* Find the fewest significant digits (1..maxprec) that read back as v, then
 * print them in plain decimal notation when the exponent is moderate (so
 * 1500 prints as 1500, not 1.5e+03) and in exponent notation otherwise.
 * The result is short for numbers written short in the source and exact
 * for all numbers. */
static void fmt(char *buf, size_t n, double v, int maxprec, int is_float)
{
    int prec = maxprec;
    for (int p = 1; p <= maxprec; p++) {
        snprintf(buf, n, "%.*e", p - 1, v);
        double back = is_float ? (double)strtof(buf, NULL) : strtod(buf, NULL);
        if (back == v) {
            prec = p;
            break;
        }
    }
    if (v == 0 || !isfinite(v)) {
        snprintf(buf, n, "%s", v == 0 ? (signbit(v) ? "-0" : "0") : buf);
        return;
    }
    char e[64];
    snprintf(e, sizeof e, "%.*e", prec - 1, v);
    int exp10 = atoi(strchr(e, 'e') + 1);
    if (exp10 >= -5 && exp10 < 17) {
        int decimals = prec - 1 - exp10;
        snprintf(buf, n, "%.*f", decimals > 0 ? decimals : 0, v);
    } else {
        snprintf(buf, n, "%s", e);
    }
}

void gls_fmt_double(char *buf, size_t n, double v) { fmt(buf, n, v, 17, 0); }
void gls_fmt_float(char *buf, size_t n, float v) { fmt(buf, n, (double)v, 9, 1); }

/* strtod over the whole token: 0 with *v and *range (errno was ERANGE),
 * or -1 if the token is not a number or is a NaN. */
static int read_number(const char *tok, double *v, int *range)
{
    char *end;
    errno = 0;
    *v = strtod(tok, &end);
    *range = errno == ERANGE;
    return end == tok || *end || isnan(*v) ? -1 : 0;
}

const char *gls_parse_double(const char *tok, double *out)
{
    double v;
    int range;
    if (read_number(tok, &v, &range) || (isinf(v) && !range))
        return "is not a finite number";
    if (isinf(v))
        return "is too large for a double (magnitudes up to 1.8e308)";
    if (v != 0 ? fabs(v) < DBL_MIN : range)
        return "is too close to zero for a double (nonzero magnitudes from 2.2e-308)";
    *out = v;
    return NULL;
}

const char *gls_parse_finite(const char *tok, double *out)
{
    double v;
    int range;
    if (read_number(tok, &v, &range) || !isfinite(v))
        return "is not a finite number";
    *out = v;
    return NULL;
}
