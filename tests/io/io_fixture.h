/* Helpers for the io tests: build fixture files byte by byte (from the formats' specifications,
 * independent of our writers) and corrupt copies of them. */
#ifndef SP_TEST_IO_FIXTURE_H
#define SP_TEST_IO_FIXTURE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A growable byte buffer; put_* append little-endian values. */
typedef struct {
    unsigned char *b;
    size_t n, cap;
} fx_buf;

static inline void fx_put(fx_buf *f, const void *p, size_t n)
{
    if (n == 0) return;
    if (f->n + n > f->cap) {
        f->cap = (f->n + n) * 2 + 64;
        f->b = realloc(f->b, f->cap);
        if (!f->b) abort();
    }
    memcpy(f->b + f->n, p, n);
    f->n += n;
}
static inline void fx_u8(fx_buf *f, uint8_t v) { fx_put(f, &v, 1); }
static inline void fx_u32(fx_buf *f, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16), (unsigned char)(v >> 24)};
    fx_put(f, b, 4);
}
static inline void fx_u64(fx_buf *f, uint64_t v)
{
    fx_u32(f, (uint32_t)v);
    fx_u32(f, (uint32_t)(v >> 32));
}
static inline void fx_i32(fx_buf *f, int32_t v) { fx_u32(f, (uint32_t)v); }
static inline void fx_i64(fx_buf *f, int64_t v) { fx_u64(f, (uint64_t)v); }
static inline void fx_f32(fx_buf *f, float v) { uint32_t u; memcpy(&u, &v, 4); fx_u32(f, u); }
static inline void fx_f64(fx_buf *f, double v) { uint64_t u; memcpy(&u, &v, 8); fx_u64(f, u); }
static inline void fx_str(fx_buf *f, const char *s) { fx_put(f, s, strlen(s)); }
static inline void fx_strz(fx_buf *f, const char *s) { fx_put(f, s, strlen(s) + 1); }
static inline void fx_free(fx_buf *f) { free(f->b); memset(f, 0, sizeof *f); }

static inline int fx_write(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    size_t w = fwrite(data, 1, n, f);
    fclose(f);
    return w == n ? 0 : -1;
}
static inline int fx_write_buf(const char *path, const fx_buf *b) { return fx_write(path, b->b, b->n); }
static inline int fx_write_text(const char *path, const char *text) { return fx_write(path, text, strlen(text)); }

/* Whole file into memory (malloc'd); NULL if unreadable. */
static inline unsigned char *fx_slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc(len > 0 ? (size_t)len : 1);
    *n = b ? fread(b, 1, (size_t)len, f) : 0;
    fclose(f);
    return b;
}

/* Copies the first `keep` bytes of src to dst (a truncated file). */
static inline int fx_truncate_copy(const char *src, const char *dst, size_t keep)
{
    size_t n;
    unsigned char *b = fx_slurp(src, &n);
    if (!b) return -1;
    int rc = fx_write(dst, b, keep < n ? keep : n);
    free(b);
    return rc;
}

static inline char *fx_path(char *out, size_t cap, const char *dir, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
    return out;
}

#endif
