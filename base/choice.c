/* Words of a fixed set (choice.h). */
#include <stdio.h>
#include <string.h>
#include "choice.h"
#include "suggest.h"

int gls_choice_find(const char *word, size_t len, const char *const *words, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (strlen(words[i]) == len && memcmp(words[i], word, len) == 0)
            return (int)i;
    return -1;
}

void gls_choice_message(char *msg, size_t msglen, const char *what, int list, const char *bad, size_t badlen,
                        const char *const *words, size_t n)
{
    if (!msglen)
        return;
    size_t k = 0;
#define PUT(...) (k += (size_t)snprintf(msg + (k < msglen ? k : msglen - 1), k < msglen ? msglen - k : 1, __VA_ARGS__))
    PUT("%s %s %s:", what, bad ? "takes" : "needs", list ? "a comma-separated list of" : "one of");
    for (size_t i = 0; i < n; i++)
        PUT("%s %s", i ? "," : "", words[i]);
    if (bad) {
        /* a value pasted by mistake can be long: its start says enough */
        int shown = badlen > 200 ? 200 : (int)badlen;
        PUT(" (not '%.*s%s')", shown, bad, badlen > 200 ? "..." : "");
        const char *s = gls_suggest(bad, badlen, words, n);
        if (s)
            PUT("; did you mean '%s'?", s);
    }
#undef PUT
}
