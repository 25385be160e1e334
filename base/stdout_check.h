/* Every tool's standard output is checked at exit: a dump, an --explain
 * plan or a camera file that did not reach its destination (a full disk,
 * a closed pipe, >/dev/full) must not exit 0. */
#ifndef GLS_STDOUT_CHECK_H
#define GLS_STDOUT_CHECK_H
#include <stddef.h>

/* Call first thing in main.  At exit, standard output is flushed and
 * closed; if any write to it failed, "TOOL: error: cannot write standard
 * output: REASON" goes to standard error and the exit status becomes 1.
 * tool must stay valid until exit (a string literal). */
void gls_check_stdout_at_exit(const char *tool);

/* Exit handlers run in the reverse order of their registration, and a
 * library loaded after main started registers its own: a GL driver
 * brings LLVM and with it libstdc++, whose exit-time destructor flushes
 * standard output before the check above would run, so that a failed
 * write's reason is gone by then ("a write failed" for glsplay --explain
 * >/dev/full, since libOSMesa, which brought them at start-up, is no
 * longer linked).  Called after such a library is loaded (glsplay, after
 * its run), it registers the check again, to run first; it runs once.
 * Nothing when gls_check_stdout_at_exit was not called. */
void gls_stdout_check_rearm(void);

/* Write n bytes (a bundle: glsc -o -) or a text (a help text, a version
 * line) to standard output, keeping the reason of a failure for the exit
 * check: what is longer than the stream's buffer is written past the
 * buffer, so nothing is left to fail again at exit and the reason would
 * otherwise be lost ("a write failed" for glsplay --help >/dev/full). */
void gls_stdout_write(const void *p, size_t n);
void gls_stdout_text(const char *text);
#endif
