/* The usage error of the tools (bad arguments): "TOOL: error: MESSAGE" on
 * standard error, then what the tool adds (its usage text after a
 * newline, or a hint on the same line), and exit status 2. */
#ifndef GLS_USAGE_H
#define GLS_USAGE_H

/* Print "TOOL: error: " and the formatted message, then after (verbatim)
 * to stderr.  Returns 2, the usage error's exit status. */
int gls_usage_error(const char *tool, const char *after, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* --version: "TOOL VERSION" on standard output (through the exit check of
 * stdout_check.h), VERSION being include/glscene.h's GLSCENE_VERSION, the
 * one place it is written (the Makefile writes it into gls_version.h for
 * usage.c).  Returns
 * 0, the exit status. */
int gls_version(const char *tool);
#endif
