/* A growing string for the text the library returns (reports, descriptions); it never prints. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/core.h"

void sp_strbuf_printf(sp_strbuf *b, const char *fmt, ...)
{
    if (b->failed) return;
    va_list ap;
    va_start(ap, fmt);
    int need = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (need < 0) {
        b->failed = 1;
        return;
    }
    if (b->len + (size_t)need + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 256;
        while (cap < b->len + (size_t)need + 1) cap *= 2;
        char *d = realloc(b->data, cap);
        if (!d) {
            b->failed = 1;
            return;
        }
        b->data = d;
        b->cap = cap;
    }
    va_start(ap, fmt);
    vsnprintf(b->data + b->len, b->cap - b->len, fmt, ap);
    va_end(ap);
    b->len += (size_t)need;
}

char *sp_strbuf_take(sp_strbuf *b)
{
    char *d = b->failed ? NULL : b->data ? b->data : calloc(1, 1);
    if (b->failed) free(b->data);
    memset(b, 0, sizeof *b);
    return d;
}

void sp_strbuf_free(sp_strbuf *b)
{
    free(b->data);
    memset(b, 0, sizeof *b);
}
