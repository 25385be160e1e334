/* The tools' usage error (usage.h). */
#include <stdarg.h>
#include <stdio.h>
#include "stdout_check.h"
#include "usage.h"
/* GLS_VERSION, written by the Makefile from include/glscene.h, the one
   place the version is */
#include "gls_version.h"

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

int gls_version(const char *tool)
{
    char line[256];
    snprintf(line, sizeof line, "%s %s\n", tool, GLS_VERSION);
    gls_stdout_text(line);
    return 0;
}
