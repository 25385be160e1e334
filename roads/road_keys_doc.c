/* spec/road.md's tables of keys, written from the parser's own table
 * (road_keys.c) by `glsroad --list-keys`; tools/spec_road_keys.sh puts
 * them into the spec and tests/e2e/road_keys.sh checks that they are
 * there, so the spec lists exactly the keys the parser takes. */
#include <stdio.h>
#include "road_keys.h"

static const char *const SECTION[RS_COUNT] = {"centre line", "cross-section", "motion"};

/* s in a Markdown table cell: '|' escaped */
static void cell(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '|')
            fputc('\\', f);
        fputc(*s, f);
    }
}

void road_list_keys(FILE *f)
{
    for (int s = 0; s < RS_COUNT; s++) {
        fprintf(f, "%s<!-- keys: %s -->\n", s ? "\n" : "", SECTION[s]);
        fputs("| key | values | given | default | meaning |\n|---|---|---|---|---|\n", f);
        for (size_t i = 0; i < road_nkeys; i++) {
            const road_key *k = &road_keys[i];
            if ((int)k->section != s)
                continue;
            fprintf(f, "| `%s` | ", k->key);
            cell(f, k->values);
            fputs(" | ", f);
            fputs(k->times                ? k->times
                  : k->repeat == RK_ONCE  ? "once"
                  : k->repeat == RK_MANY  ? "any number"
                                          : "the last counts",
                  f);
            if (k->excludes)
                fprintf(f, ", not with `%s`", k->excludes);
            fputs(" | ", f);
            if (k->deflt)
                fputs(k->deflt, f);
            for (int j = 0; !k->deflt && j < (int)(sizeof k->val / sizeof k->val[0]) && k->val[j].what; j++)
                fprintf(f, "%s%g", j ? " " : "", k->val[j].def);
            fprintf(f, " | %s |\n", k->meaning);
        }
        fputs("<!-- end of keys -->\n", f);
    }
}
