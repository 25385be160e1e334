/* The scene language scanner, for re2c (lexer.h says what it promises).
 * The source buffer ends with a NUL sentinel (the loader guarantees it); a
 * NUL before the end is an error token.  Token codes come from lemon's
 * generated grammar.h.  Whitespace and comments are skipped here; line and
 * column are tracked for messages.  Nothing here prints: errors are
 * TK_INVALID tokens, reported by the driver (unit.c). */
#include <stdio.h>
#include "grammar.h"
#include "lexer.h"

void gls_lexer_init(gls_lexer *lx, const char *text, size_t len)
{
    *lx = (gls_lexer){text, text + len, text, text, 1};
}

int gls_lex(gls_lexer *lx, gls_tok *t)
{
    const char *YYMARKER;
    for (;;) {
        lx->tok = lx->cur;
        t->p = lx->tok;
        t->line = lx->line;
        t->col = (unsigned)(lx->tok - lx->line_start) + 1;
        t->err = GLS_LEX_OK;
#define TOKEN(code) do { t->len = (uint32_t)(lx->cur - lx->tok); return TK_##code; } while (0)
#define INVALID(e) do { t->err = (e); TOKEN(INVALID); } while (0)
        /*!re2c
        re2c:define:YYCTYPE = "unsigned char";
        re2c:define:YYCURSOR = "lx->cur";
        re2c:yyfill:enable = 0;
        re2c:flags:utf-8 = 0;

        digits = [0-9]+;
        exp    = [eE] [+-]? digits;
        number = (digits ("." [0-9]*)? | "." digits) exp?;
        ident  = [A-Za-z_] [A-Za-z0-9_]*;

        "\x00" {
            if (lx->tok >= lx->lim) { lx->cur = lx->tok; t->len = 0; return 0; }
            INVALID(GLS_LEX_NUL);
        }
        "\n"            { lx->line++; lx->line_start = lx->cur; continue; }
        [ \t\r\f\v]+    { continue; }
        "//" [^\n\x00]* { continue; }
        "/*"            {
            /* block comment: scan by hand to count lines and find the end */
            for (;;) {
                if (lx->cur >= lx->lim)
                    INVALID(GLS_LEX_UNTERMINATED_COMMENT);
                if (lx->cur[0] == '*' && lx->cur[1] == '/') { lx->cur += 2; break; }
                if (lx->cur[0] == '\n') { lx->line++; lx->line_start = lx->cur + 1; }
                lx->cur++;
            }
            continue;
        }
        "const"         { TOKEN(CONST); }
        "param"         { TOKEN(PARAM); }
        "repeat"        { TOKEN(REPEAT); }
        ident           { TOKEN(IDENT); }
        number          { TOKEN(NUMBER); }
        number [A-Za-z_0-9.]+ { INVALID(GLS_LEX_MALFORMED_NUMBER); }
        "\"" [^"\n\x00]* "\"" { TOKEN(STRING); }
        "\"" [^"\n\x00]* { INVALID(GLS_LEX_UNTERMINATED_STRING); }
        "("  { TOKEN(LPAREN); }
        ")"  { TOKEN(RPAREN); }
        "{"  { TOKEN(LBRACE); }
        "}"  { TOKEN(RBRACE); }
        ","  { TOKEN(COMMA); }
        ";"  { TOKEN(SEMI); }
        "="  { TOKEN(ASSIGN); }
        "+"  { TOKEN(PLUS); }
        "-"  { TOKEN(MINUS); }
        "*"  { TOKEN(STAR); }
        "/"  { TOKEN(SLASH); }
        [^] {
            unsigned char ch = (unsigned char)*lx->tok;
            INVALID(ch >= 0x20 && ch < 0x7f ? GLS_LEX_UNEXPECTED_CHARACTER : GLS_LEX_UNEXPECTED_BYTE);
        }
        */
#undef INVALID
#undef TOKEN
    }
}

int gls_lex_message(const gls_tok *t, char *buf, size_t n)
{
    switch (t->err) {
    case GLS_LEX_NUL: return snprintf(buf, n, "NUL byte in source");
    case GLS_LEX_UNTERMINATED_COMMENT: return snprintf(buf, n, "unterminated comment");
    case GLS_LEX_MALFORMED_NUMBER: return snprintf(buf, n, "malformed number '%.*s'", (int)t->len, t->p);
    case GLS_LEX_UNTERMINATED_STRING: return snprintf(buf, n, "unterminated string");
    case GLS_LEX_UNEXPECTED_CHARACTER: return snprintf(buf, n, "unexpected character '%c'", *t->p);
    case GLS_LEX_UNEXPECTED_BYTE: return snprintf(buf, n, "unexpected byte 0x%02x", (unsigned char)*t->p);
    case GLS_LEX_OK: break;
    }
    return snprintf(buf, n, "no lexical error");
}
