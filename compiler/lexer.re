/* The scene language scanner, for re2c.  The source buffer ends with a NUL
 * sentinel (the loader guarantees it); a NUL before the end is an error.
 * Token codes come from lemon's generated grammar.h.  Whitespace and
 * comments are skipped here; line and column are tracked for messages. */
#include "grammar.h"
#include "parse.h"

/* Returns the next token code, 0 at end of input.  Lexical errors are
 * reported here and the offending bytes skipped. */
int gls_lex(gls_lexer *lx, gls_tok *t, gls_parse *ctx)
{
    const char *YYMARKER;
    for (;;) {
        lx->tok = lx->cur;
        t->p = lx->tok;
        t->line = lx->line;
        t->col = (unsigned)(lx->tok - lx->line_start) + 1;
#define TOKEN(code) do { t->len = (uint32_t)(lx->cur - lx->tok); return TK_##code; } while (0)
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
            gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "NUL byte in source");
            continue;
        }
        "\n"            { lx->line++; lx->line_start = lx->cur; continue; }
        [ \t\r\f\v]+    { continue; }
        "//" [^\n\x00]* { continue; }
        "/*"            {
            /* block comment: scan by hand to count lines and find the end */
            for (;;) {
                if (lx->cur >= lx->lim) {
                    gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "unterminated comment");
                    ctx->lex_eof_error = 1;
                    t->len = 0;
                    return 0;
                }
                if (lx->cur[0] == '*' && lx->cur[1] == '/') { lx->cur += 2; break; }
                if (lx->cur[0] == '\n') { lx->line++; lx->line_start = lx->cur + 1; }
                lx->cur++;
            }
            continue;
        }
        "const"         { TOKEN(CONST); }
        ident           { TOKEN(IDENT); }
        number          { TOKEN(NUMBER); }
        number [A-Za-z_0-9.]+ {
            gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "malformed number '%.*s'",
                         (int)(lx->cur - lx->tok), lx->tok);
            TOKEN(NUMBER);
        }
        "\"" [^"\n\x00]* "\"" { TOKEN(STRING); }
        "\"" [^"\n\x00]* {
            gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "unterminated string");
            ctx->lex_eof_error = 1;
            continue;
        }
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
            if (ch >= 0x20 && ch < 0x7f)
                gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "unexpected character '%c'", ch);
            else
                gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "unexpected byte 0x%02x", ch);
            continue;
        }
        */
#undef TOKEN
    }
}
