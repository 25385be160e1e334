/* Unit tests of the scanner (compiler/lexer.re, lexer.h) on its own: token
 * kinds, texts, lines and columns; every error token with its message; the
 * NUL sentinel; CRLF line ends; long inputs.  spec/language.md section 3
 * is what it implements. */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "grammar.h"
#include "lexer.h"

/* The scanner needs text[len] == NUL: keep a NUL-terminated copy. */
typedef struct {
    char *text;
    gls_lexer lx;
} scan;

static void scan_open(scan *s, const char *text, size_t len)
{
    s->text = malloc(len + 1);
    memcpy(s->text, text, len);
    s->text[len] = 0;
    gls_lexer_init(&s->lx, s->text, len);
}

#define SCAN(s, lit) scan_open((s), (lit), sizeof(lit) - 1)

/* The next token is code, with text txt at line:col. */
static int expect(scan *s, int code, const char *txt, unsigned line, unsigned col)
{
    gls_tok t;
    int got = gls_lex(&s->lx, &t);
    int ok = got == code && t.len == strlen(txt) && memcmp(t.p, txt, t.len) == 0 && t.line == line && t.col == col;
    CHECK_MSG(ok, "got code %d '%.*s' at %u:%u, expected code %d '%s' at %u:%u", got, (int)t.len, t.p, t.line,
              t.col, code, txt, line, col);
    return ok;
}

/* The next token is an error token err at line:col, with message msg. */
static void expect_error(scan *s, gls_lex_error err, unsigned line, unsigned col, const char *msg)
{
    gls_tok t;
    int got = gls_lex(&s->lx, &t);
    char buf[256];
    gls_lex_message(&t, buf, sizeof buf);
    CHECK_MSG(got == TK_INVALID && t.err == err && t.line == line && t.col == col,
              "got code %d err %d at %u:%u, expected TK_INVALID err %d at %u:%u", got, (int)t.err, t.line, t.col,
              (int)err, line, col);
    CHECK_STR(buf, msg);
}

static void expect_end(scan *s)
{
    gls_tok t;
    for (int i = 0; i < 3; i++) /* and stays at the end */
        CHECK(gls_lex(&s->lx, &t) == 0 && t.len == 0);
    free(s->text);
}

static void test_token_kinds_and_positions(void)
{
    scan s;
    SCAN(&s, "const lane = 3.5e2;\n"
             "  trans(-lane, +1, .5) poly{}\n"
             "\tx_1*2/3, \"a.b\"");
    expect(&s, TK_CONST, "const", 1, 1);
    expect(&s, TK_IDENT, "lane", 1, 7);
    expect(&s, TK_ASSIGN, "=", 1, 12);
    expect(&s, TK_NUMBER, "3.5e2", 1, 14);
    expect(&s, TK_SEMI, ";", 1, 19);
    expect(&s, TK_IDENT, "trans", 2, 3);
    expect(&s, TK_LPAREN, "(", 2, 8);
    expect(&s, TK_MINUS, "-", 2, 9);
    expect(&s, TK_IDENT, "lane", 2, 10);
    expect(&s, TK_COMMA, ",", 2, 14);
    expect(&s, TK_PLUS, "+", 2, 16);
    expect(&s, TK_NUMBER, "1", 2, 17);
    expect(&s, TK_COMMA, ",", 2, 18);
    expect(&s, TK_NUMBER, ".5", 2, 20);
    expect(&s, TK_RPAREN, ")", 2, 22);
    expect(&s, TK_IDENT, "poly", 2, 24);
    expect(&s, TK_LBRACE, "{", 2, 28);
    expect(&s, TK_RBRACE, "}", 2, 29);
    expect(&s, TK_IDENT, "x_1", 3, 2); /* a tab is one column */
    expect(&s, TK_STAR, "*", 3, 5);
    expect(&s, TK_NUMBER, "2", 3, 6);
    expect(&s, TK_SLASH, "/", 3, 7);
    expect(&s, TK_NUMBER, "3", 3, 8);
    expect(&s, TK_COMMA, ",", 3, 9);
    expect(&s, TK_STRING, "\"a.b\"", 3, 11);
    expect_end(&s);

    /* numbers of every form; "constant" and "const_" are identifiers */
    SCAN(&s, "3 3. 3.5 .5 1e3 1.e-3 007 1E+2 constant const_ _");
    const char *nums[] = {"3", "3.", "3.5", ".5", "1e3", "1.e-3", "007", "1E+2"};
    for (unsigned i = 0, col = 1; i < sizeof nums / sizeof nums[0]; col += (unsigned)strlen(nums[i]) + 1, i++)
        expect(&s, TK_NUMBER, nums[i], 1, col);
    expect(&s, TK_IDENT, "constant", 1, 32);
    expect(&s, TK_IDENT, "const_", 1, 41);
    expect(&s, TK_IDENT, "_", 1, 48);
    expect_end(&s);
}

/* Comments are skipped, count their lines, and do not nest. */
static void test_comments(void)
{
    scan s;
    SCAN(&s, "a // b ( \" /*\n"
             "c /* d\n"
             " e /* f */ g\n"
             "/**/h/***/i");
    expect(&s, TK_IDENT, "a", 1, 1);
    expect(&s, TK_IDENT, "c", 2, 1);
    expect(&s, TK_IDENT, "g", 3, 12);
    expect(&s, TK_IDENT, "h", 4, 5);
    expect(&s, TK_IDENT, "i", 4, 11);
    expect_end(&s);
}

/* Every error token: its kind, position, message, and how scanning goes on. */
static void test_error_tokens(void)
{
    scan s;
    SCAN(&s, "a @ b\x01 \x80;");
    expect(&s, TK_IDENT, "a", 1, 1);
    expect_error(&s, GLS_LEX_UNEXPECTED_CHARACTER, 1, 3, "unexpected character '@'");
    expect(&s, TK_IDENT, "b", 1, 5);
    expect_error(&s, GLS_LEX_UNEXPECTED_BYTE, 1, 6, "unexpected byte 0x01");
    expect_error(&s, GLS_LEX_UNEXPECTED_BYTE, 1, 8, "unexpected byte 0x80");
    expect(&s, TK_SEMI, ";", 1, 9);
    expect_end(&s);

    /* a malformed number is one token, whole */
    SCAN(&s, "1.2.3 0x10 1e 1e5x 2ab 7");
    expect_error(&s, GLS_LEX_MALFORMED_NUMBER, 1, 1, "malformed number '1.2.3'");
    expect_error(&s, GLS_LEX_MALFORMED_NUMBER, 1, 7, "malformed number '0x10'");
    expect_error(&s, GLS_LEX_MALFORMED_NUMBER, 1, 12, "malformed number '1e'");
    expect_error(&s, GLS_LEX_MALFORMED_NUMBER, 1, 15, "malformed number '1e5x'");
    expect_error(&s, GLS_LEX_MALFORMED_NUMBER, 1, 20, "malformed number '2ab'");
    expect(&s, TK_NUMBER, "7", 1, 24);
    expect_end(&s);

    /* an unterminated string is skipped to the end of its line */
    SCAN(&s, "call(\"a.b);\nx");
    expect(&s, TK_IDENT, "call", 1, 1);
    expect(&s, TK_LPAREN, "(", 1, 5);
    expect_error(&s, GLS_LEX_UNTERMINATED_STRING, 1, 6, "unterminated string");
    expect(&s, TK_IDENT, "x", 2, 1);
    expect_end(&s);

    /* an unterminated comment ends the input, reported at its start */
    SCAN(&s, "a\n  /* b\nc\n");
    expect(&s, TK_IDENT, "a", 1, 1);
    expect_error(&s, GLS_LEX_UNTERMINATED_COMMENT, 2, 3, "unterminated comment");
    expect_end(&s);
    CHECK(s.lx.line == 4); /* the comment's lines were counted */

    /* a NUL byte before the end is skipped */
    SCAN(&s, "a\0b");
    expect(&s, TK_IDENT, "a", 1, 1);
    expect_error(&s, GLS_LEX_NUL, 1, 2, "NUL byte in source");
    expect(&s, TK_IDENT, "b", 1, 3);
    expect_end(&s);
}

/* The NUL at text[len] ends the input, wherever the scanner is: empty
 * input, after a line comment without a newline, in a string. */
static void test_nul_sentinel(void)
{
    scan s;
    SCAN(&s, "");
    expect_end(&s);
    SCAN(&s, "x // no newline");
    expect(&s, TK_IDENT, "x", 1, 1);
    expect_end(&s);
    SCAN(&s, "\"abc");
    expect_error(&s, GLS_LEX_UNTERMINATED_STRING, 1, 1, "unterminated string");
    expect_end(&s);
    SCAN(&s, "/*");
    expect_error(&s, GLS_LEX_UNTERMINATED_COMMENT, 1, 1, "unterminated comment");
    expect_end(&s);
    SCAN(&s, "/* *");
    expect_error(&s, GLS_LEX_UNTERMINATED_COMMENT, 1, 1, "unterminated comment");
    expect_end(&s);
    /* the scanner stops at the length given, not at an earlier NUL */
    SCAN(&s, "a\0");
    expect(&s, TK_IDENT, "a", 1, 1);
    expect_error(&s, GLS_LEX_NUL, 1, 2, "NUL byte in source");
    expect_end(&s);
}

/* Only LF ends a line: CR is whitespace, so CRLF files give the same lines
 * and columns, and a CR inside a string is part of it. */
static void test_crlf(void)
{
    scan s;
    SCAN(&s, "push;\r\n  pop;\r\n\r\n\"a\rb\"\r");
    expect(&s, TK_IDENT, "push", 1, 1);
    expect(&s, TK_SEMI, ";", 1, 5);
    expect(&s, TK_IDENT, "pop", 2, 3);
    expect(&s, TK_SEMI, ";", 2, 6);
    expect(&s, TK_STRING, "\"a\rb\"", 4, 1);
    expect_end(&s);
    CHECK(s.lx.line == 4);
}

/* Long inputs: a 1 MiB identifier and a 1 MiB malformed number are one
 * token each, the malformed number's message quotes it whole; 100,000
 * lines keep their numbers; a long line keeps its columns. */
static void test_long_inputs(void)
{
    enum { BIG = 1 << 20, LINES = 100000 };
    char *text = malloc(BIG + 16);
    scan s;

    memset(text, 'x', BIG);
    memcpy(text + BIG, " 1", 2);
    scan_open(&s, text, BIG + 2);
    gls_tok t;
    CHECK(gls_lex(&s.lx, &t) == TK_IDENT && t.len == BIG && t.p == s.text);
    CHECK(gls_lex(&s.lx, &t) == TK_NUMBER && t.line == 1 && t.col == BIG + 2);
    expect_end(&s);

    text[0] = '9';
    memset(text + 1, '.', BIG - 1);
    scan_open(&s, text, BIG);
    CHECK(gls_lex(&s.lx, &t) == TK_INVALID && t.err == GLS_LEX_MALFORMED_NUMBER && t.len == BIG);
    char *msg = malloc(BIG + 64);
    char small[32];
    int need = gls_lex_message(&t, small, sizeof small);
    CHECK(need == BIG + (int)strlen("malformed number ''"));
    CHECK(gls_lex_message(&t, msg, (size_t)need + 1) == need);
    CHECK(memcmp(msg, "malformed number '9...", 22) == 0 && msg[need - 1] == '\'' && msg[need] == 0);
    CHECK(memcmp(small, msg, sizeof small - 1) == 0 && small[sizeof small - 1] == 0);
    free(msg);
    expect_end(&s);
    free(text);

    text = malloc(LINES * 3 + 1);
    for (int i = 0; i < LINES; i++)
        memcpy(text + 3 * i, "a;\n", 3);
    scan_open(&s, text, LINES * 3);
    unsigned bad = 0;
    for (unsigned i = 0; i < LINES; i++) {
        bad += gls_lex(&s.lx, &t) != TK_IDENT || t.line != i + 1 || t.col != 1;
        bad += gls_lex(&s.lx, &t) != TK_SEMI || t.line != i + 1 || t.col != 2;
    }
    CHECK(bad == 0);
    expect_end(&s);
    CHECK(s.lx.line == LINES + 1);
    free(text);
}

int main(void)
{
    RUN(test_token_kinds_and_positions);
    RUN(test_comments);
    RUN(test_error_tokens);
    RUN(test_nul_sentinel);
    RUN(test_crlf);
    RUN(test_long_inputs);
    CHECK_EXIT();
}
