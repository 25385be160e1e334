/* The tools' usage error (usage.h). */
#include <stdarg.h>
#include <stdio.h>
#include "usage.h"

int gls_usage_error(const char *tool, const char *after, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: error: ", tool);
    vfprintf(stderr, fmt, ap);
    fputs(after, stderr);
    va_end(ap);
    return 2;
}
