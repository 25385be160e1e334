/* The exit-time check of standard output (stdout_check.h), after gnulib's
 * close_stdout: an atexit handler runs on every path out of main, so no
 * return statement can forget it. */
#include <errno.h>
#include <stdio.h>
#include <stdio_ext.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "stdout_check.h"

static const char *tool_name;
static int first_err; /* errno of the first failed gls_stdout_text */
static int checked;   /* close_stdout has run (it may be registered twice) */

void gls_stdout_write(const void *p, size_t n)
{
    errno = 0;
    if (fwrite(p, 1, n, stdout) != n && !first_err)
        first_err = errno;
}

void gls_stdout_text(const char *text)
{
    gls_stdout_write(text, strlen(text));
}

static void close_stdout(void)
{
    if (checked)
        return;
    checked = 1;
    int pending = __fpending(stdout) != 0;
    int failed_before = ferror(stdout);
    errno = 0;
    int close_failed = fclose(stdout) != 0;
    int err = errno;
    /* a standard output closed by the caller (>&-) that was never written
       to is not an error */
    if (!failed_before && (!close_failed || (err == EBADF && !pending)))
        return;
    /* an earlier failed write leaves its errno long gone; closing usually
       retries the unwritten buffer and fails the same way */
    fprintf(stderr, "%s: error: cannot write standard output: %s\n", tool_name,
            first_err ? strerror(first_err) : close_failed && err ? strerror(err) : "a write failed");
    _exit(1); /* exit() may not be called from an exit handler */
}

void gls_check_stdout_at_exit(const char *tool)
{
    tool_name = tool;
    atexit(close_stdout);
}

void gls_stdout_check_rearm(void)
{
    if (tool_name && !checked)
        atexit(close_stdout);
}
