/* The scene language scanner (lexer.re): bytes in, tokens out, nothing
 * printed.  A lexical error is a token of its own, TK_INVALID, carrying its
 * position and what is wrong (err); the driver (unit.c) reports it with
 * gls_lex_message() and decides what the parser sees instead.  Token codes
 * are lemon's (grammar.h); spec/language.md section 3 is the normative
 * description. */
#ifndef GLS_LEXER_H
#define GLS_LEXER_H
#include <stddef.h>
#include <stdint.h>

/* What is wrong with a TK_INVALID token, and how scanning goes on. */
typedef enum {
    GLS_LEX_OK = 0,
    GLS_LEX_NUL,                  /* a NUL byte before the end: skipped     */
    GLS_LEX_UNTERMINATED_COMMENT, /* a block comment without its end: the
                                     input ends                             */
    GLS_LEX_MALFORMED_NUMBER,     /* "1.2.3", "0x10": stands for a NUMBER  */
    GLS_LEX_UNTERMINATED_STRING,  /* skipped to the end of its line         */
    GLS_LEX_UNEXPECTED_CHARACTER, /* a printable ASCII byte: skipped        */
    GLS_LEX_UNEXPECTED_BYTE,      /* any other byte: skipped                */
} gls_lex_error;

/* A token: its bytes, where it starts (1-based line, byte column) and, for
 * TK_INVALID, what is wrong. */
typedef struct {
    const char *p;
    uint32_t len;
    unsigned line, col;
    gls_lex_error err;
} gls_tok;

typedef struct {
    const char *cur, *lim, *line_start, *tok;
    unsigned line;
} gls_lexer;

/* Scan text[0..len); text[len] must be NUL (the loader's sentinel). */
void gls_lexer_init(gls_lexer *lx, const char *text, size_t len);

/* The next token's code, 0 at the end of the input (and on every call
 * after it).  Whitespace and comments are skipped; line and column are
 * tracked (only LF ends a line). */
int gls_lex(gls_lexer *lx, gls_tok *t);

/* The message of a TK_INVALID token, as snprintf writes it: the return
 * value is the full length, which may exceed n (a malformed number is
 * quoted whole). */
int gls_lex_message(const gls_tok *t, char *buf, size_t n);
#endif
