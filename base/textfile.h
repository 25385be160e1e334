/* Reading text inputs (camera files, trajectories, road descriptions)
 * with bounds: a whole file is read only up to a stated size, and no line
 * may be longer than GLS_TEXT_MAX_LINE bytes, so that a wrong path
 * (/dev/zero, a bundle, a huge log) is refused after a bounded amount of
 * memory and time instead of being read to the end. */
#ifndef GLS_TEXTFILE_H
#define GLS_TEXTFILE_H
#include <stddef.h>
#include <stdio.h>

/* The longest line of any text input, newline excluded.  The formats are
 * a few numbers per line (a trajectory line is under 400 bytes). */
#define GLS_TEXT_MAX_LINE 4095u

/* Read the text file at path whole: at most limit bytes, from a regular
 * file (readfile.h: anything else is refused with what it is).  Returns a
 * malloc'd buffer with a NUL after its *len bytes, or NULL with one line
 * "path: error: why" in err; what names the input ("camera file") in the
 * size and directory messages. */
char *gls_text_read(const char *path, size_t limit, const char *what, size_t *len, char *err, size_t errlen);

/* Open the text file at path to read it a line at a time (trajectories
 * and motion files, which may be long): a stream, or NULL with the reason
 * in why, without the path ("cannot open: No such file or directory",
 * "cannot read: it is a FIFO (named pipe), not a regular file", "is a
 * directory, not a WHAT"), for the caller to place. */
FILE *gls_text_open(const char *path, const char *what, char *why, size_t whylen);

/* Lines of a text held in memory.  Start with {text, len} and line = 0. */
typedef struct {
    const char *text;
    size_t len;
    size_t pos;    /* start of the next line                            */
    unsigned line; /* 1-based number of the line last returned          */
} gls_text_lines;

/* The next line (without its '\n'), copied into buf with a NUL after its
 * *n bytes (it may hold NUL bytes of its own): 1, 0 at the end, -1 if it
 * is longer than GLS_TEXT_MAX_LINE bytes (nothing copied; it->line is its
 * number: report it at column GLS_TEXT_MAX_LINE + 1, where it overflows). */
int gls_text_next_line(gls_text_lines *it, char buf[GLS_TEXT_MAX_LINE + 1], size_t *n);

/* Split a line (NUL-terminated; it is modified) into words, the one
 * tokenizer of the key/value text formats (camera files, road
 * descriptions, trajectories): the line is cut at its first character
 * from cut (a comment: "#"), the rest split at characters from seps.
 * tok[i] points into line, so a word's column is tok[i] - line + 1.
 * Returns the number of words, at most max: a caller that accepts n words
 * passes max = n + 1 and reads a result of n + 1 as "too many". */
int gls_text_split(char *line, const char *cut, const char *seps, char **tok, int max);

/* Read one line of a stream into buf (capacity GLS_TEXT_MAX_LINE + 1),
 * without its '\n', NUL-terminated; *n is its length (it may hold NUL
 * bytes).  Returns 1 for a line, 0 at the end of the stream, -1 if the
 * line is longer than GLS_TEXT_MAX_LINE bytes (reading stops there), -2 on
 * a read error (errno set).  Memory stays bounded however long the line. */
int gls_text_getline(FILE *f, char buf[GLS_TEXT_MAX_LINE + 1], size_t *n);

#endif
