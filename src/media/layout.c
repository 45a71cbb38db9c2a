/* Text layout for the canvas: UTF-8 cleaning and greedy line breaking against a width measure.
 * Kept apart from Cairo so the rules can be tested with a fake measure. */
#include <stdlib.h>
#include <string.h>

#include "media/media_internal.h"

/* Length of the valid UTF-8 sequence at s, 0 when it is not one (RFC 3629's table). */
static int utf8_valid_len(const unsigned char *s)
{
    unsigned char b = s[0];
    if (b < 0x80) return 1;
    int n;
    unsigned char lo = 0x80, hi = 0xbf;
    if (b >= 0xc2 && b <= 0xdf) n = 2;
    else if (b >= 0xe0 && b <= 0xef) {
        n = 3;
        if (b == 0xe0) lo = 0xa0;
        if (b == 0xed) hi = 0x9f; /* no surrogates */
    } else if (b >= 0xf0 && b <= 0xf4) {
        n = 4;
        if (b == 0xf0) lo = 0x90;
        if (b == 0xf4) hi = 0x8f; /* nothing above U+10FFFF */
    } else return 0;
    if (s[1] < lo || s[1] > hi) return 0;
    for (int k = 2; k < n; k++)
        if (s[k] < 0x80 || s[k] > 0xbf) return 0;
    return n;
}

char *media_sanitize(const char *text)
{
    size_t n = strlen(text);
    char *out = malloc(n + 1);
    if (!out) return NULL;
    const unsigned char *s = (const unsigned char *)text;
    size_t o = 0;
    for (size_t i = 0; i < n;) {
        unsigned char b = s[i];
        int len = utf8_valid_len(s + i);
        int c1 = len == 2 && b == 0xc2 && s[i + 1] < 0xa0; /* U+0080..U+009F: C1 controls */
        if (b == '\n') out[o++] = '\n';
        else if (b == '\t') out[o++] = ' ';
        else if (len == 0 || c1 || b < 0x20 || b == 0x7f) out[o++] = '?';
        else {
            memcpy(out + o, s + i, (size_t)len);
            o += (size_t)len;
            i += (size_t)len;
            continue;
        }
        i += (len == 2 && c1) ? 2 : 1;
    }
    out[o] = 0;
    return out;
}

/* Bytes of the code point starting at s (s is sanitized, so the lead byte says). */
static size_t cp_len(const char *s)
{
    unsigned char b = (unsigned char)s[0];
    return b < 0x80 ? 1 : b < 0xe0 ? 2 : b < 0xf0 ? 3 : 4;
}

typedef struct builder {
    media_lines *out;
    int cap, full;
    media_width_fn width;
    void *ctx;
    float wrap;
} builder;

static int push(builder *b, const char *s, size_t n)
{
    if (b->out->n >= MEDIA_MAX_LINES) {
        b->full = 1;
        return 0;
    }
    if (b->out->n == b->cap) {
        int cap = b->cap ? 2 * b->cap : 8;
        char **nl = realloc(b->out->line, (size_t)cap * sizeof *nl);
        if (!nl) return -1;
        b->out->line = nl;
        b->cap = cap;
    }
    if (n > MEDIA_MAX_LINE) { /* cut at a code point boundary */
        size_t k = 0;
        while (k + cp_len(s + k) <= MEDIA_MAX_LINE) k += cp_len(s + k);
        n = k;
    }
    char *l = malloc(n + 1);
    if (!l) return -1;
    memcpy(l, s, n);
    l[n] = 0;
    b->out->line[b->out->n++] = l;
    return 0;
}

static int fits(const builder *b, const char *s, size_t n)
{
    if (n > MEDIA_MAX_LINE) return 0;
    return b->wrap <= 0 || b->width(b->ctx, s, n) <= b->wrap;
}

/* One paragraph (no '\n'), wrapped at spaces; words too wide for a line broken by characters. */
static int wrap_paragraph(builder *b, const char *p, size_t n)
{
    char *cur = malloc(n + 2);
    if (!cur) return -1;
    size_t len = 0, i = 0;
    int rc = 0, first = b->out->n;
    while (i < n && !rc) {
        while (i < n && p[i] == ' ') i++;
        size_t ws = i;
        while (i < n && p[i] != ' ') i++;
        if (i == ws) break;
        size_t wl = i - ws;
        size_t save = len;
        if (len) cur[len++] = ' ';
        memcpy(cur + len, p + ws, wl);
        if (fits(b, cur, len + wl)) {
            len += wl;
            continue;
        }
        len = save;
        if (len) {
            rc = push(b, cur, len);
            len = 0;
        }
        const char *w = p + ws;
        while (wl && !rc) {
            if (fits(b, w, wl)) {
                memcpy(cur, w, wl);
                len = wl;
                break;
            }
            size_t k = cp_len(w); /* at least one code point per line */
            while (k < wl && fits(b, w, k + cp_len(w + k))) k += cp_len(w + k);
            rc = push(b, w, k);
            w += k;
            wl -= k;
        }
    }
    if (!rc && (len || b->out->n == first)) rc = push(b, cur, len); /* "" for a blank paragraph */
    free(cur);
    return rc;
}

/* The last kept line ends with "..." and still fits. */
static int ellipsize(builder *b, int last)
{
    char *l = b->out->line[last];
    size_t n = strlen(l);
    char *e = malloc(n + 4);
    if (!e) return -1;
    memcpy(e, l, n);
    for (;;) {
        memcpy(e + n, "...", 4);
        if (n == 0 || fits(b, e, n + 3)) break;
        size_t k = 0, prev = 0;
        while (k < n) { prev = k; k += cp_len(e + k); }
        n = prev;
    }
    free(l);
    b->out->line[last] = e;
    return 0;
}

int media_layout(const char *text, float wrap_px, int max_lines, media_width_fn width, void *ctx,
                 media_lines *out)
{
    memset(out, 0, sizeof *out);
    char *s = media_sanitize(text ? text : "");
    if (!s) return -1;
    builder b = {.out = out, .width = width, .ctx = ctx, .wrap = wrap_px};
    int rc = 0;
    for (const char *p = s; !rc && !b.full;) {
        const char *e = strchr(p, '\n');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        rc = wrap_px > 0 ? wrap_paragraph(&b, p, n) : push(&b, p, n);
        if (!e) break;
        p = e + 1;
    }
    free(s);
    if (!rc && max_lines > 0 && (out->n > max_lines || b.full)) {
        int keep = out->n < max_lines ? out->n : max_lines;
        for (int i = keep; i < out->n; i++) free(out->line[i]);
        out->n = keep;
        if (keep > 0) rc = ellipsize(&b, keep - 1);
    }
    if (rc) media_lines_free(out);
    return rc;
}

void media_lines_free(media_lines *l)
{
    if (!l) return;
    for (int i = 0; i < l->n; i++) free(l->line[i]);
    free(l->line);
    memset(l, 0, sizeof *l);
}
