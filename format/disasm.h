/* The stable, diffable text dump of a bundle (glsdis). */
#ifndef GLS_DISASM_H
#define GLS_DISASM_H
#include <stdio.h>
#include "bundle.h"
/* with_source: append "; file:line" to each instruction. */
void gls_disassemble(const gls_bundle *b, FILE *out, int with_source);
#endif
