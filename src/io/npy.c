/* .npy arrays (NumPy format versions 1-3): how feature maps and PCA bases travel between
 * semsplat and any Python extractor. Also the dtype table and half / bfloat16 conversions. */
#include "io_internal.h"

#include <ctype.h>
#include <stdlib.h>

size_t sp_dtype_size(sp_dtype t)
{
    switch (t) {
    case SP_DTYPE_F32: case SP_DTYPE_I32: return 4;
    case SP_DTYPE_F16: case SP_DTYPE_U16: case SP_DTYPE_BF16: return 2;
    case SP_DTYPE_U8: return 1;
    case SP_DTYPE_F64: case SP_DTYPE_I64: return 8;
    }
    return 0;
}

const char *io_dtype_name(sp_dtype t)
{
    switch (t) {
    case SP_DTYPE_F32: return "float32";
    case SP_DTYPE_F16: return "float16";
    case SP_DTYPE_U8: return "uint8";
    case SP_DTYPE_I32: return "int32";
    case SP_DTYPE_U16: return "uint16";
    case SP_DTYPE_F64: return "float64";
    case SP_DTYPE_I64: return "int64";
    case SP_DTYPE_BF16: return "bfloat16";
    }
    return "?";
}

/* IEEE 754 binary16 <-> binary32, with subnormals, infinities and NaN; rounding to nearest even. */
float sp_half_to_float(uint16_t h)
{
    uint32_t sign = (uint32_t)(h & 0x8000) << 16, exp = (h >> 10) & 0x1F, man = h & 0x3FF, bits;
    if (exp == 0) {
        if (man == 0) {
            bits = sign;
        } else { /* subnormal: renormalise */
            int e = -1;
            do {
                e++;
                man <<= 1;
            } while (!(man & 0x400));
            bits = sign | ((uint32_t)(127 - 15 - e) << 23) | ((man & 0x3FF) << 13);
        }
    } else if (exp == 31) {
        bits = sign | 0x7F800000u | (man << 13);
    } else {
        bits = sign | ((exp + 127 - 15) << 23) | (man << 13);
    }
    float f;
    memcpy(&f, &bits, 4);
    return f;
}

uint16_t sp_float_to_half(float f)
{
    uint32_t x;
    memcpy(&x, &f, 4);
    uint16_t sign = (uint16_t)((x >> 16) & 0x8000);
    uint32_t exp = (x >> 23) & 0xFF, man = x & 0x7FFFFF;
    if (exp == 0xFF) return sign | 0x7C00 | (man ? 0x200 : 0); /* Inf / quiet NaN */
    int e = (int)exp - 127 + 15;
    if (e >= 31) return sign | 0x7C00; /* overflow -> Inf */
    if (e <= 0) {
        if (e < -10) return sign; /* underflow -> signed zero */
        man |= 0x800000;
        int shift = 14 - e;
        uint32_t half = man >> shift, rem = man & ((1u << shift) - 1), mid = 1u << (shift - 1);
        if (rem > mid || (rem == mid && (half & 1))) half++;
        return sign | (uint16_t)half;
    }
    uint32_t half = ((uint32_t)e << 10) | (man >> 13), rem = man & 0x1FFF;
    if (rem > 0x1000 || (rem == 0x1000 && (half & 1))) half++; /* may carry into Inf: correct */
    return sign | (uint16_t)half;
}

float sp_bf16_to_float(uint16_t h)
{
    uint32_t bits = (uint32_t)h << 16;
    float f;
    memcpy(&f, &bits, 4);
    return f;
}

/* ---- reading ---------------------------------------------------------------------------------- */

size_t sp_npy_count(const sp_npy *a)
{
    size_t n = 1;
    for (int i = 0; i < a->ndim; i++) n *= a->shape[i];
    return n;
}

void sp_npy_free(sp_npy *a)
{
    if (!a) return;
    sp_free(a->data);
    memset(a, 0, sizeof *a);
}

/* Finds `'key':` in the header dict and returns the text after the colon, or NULL. */
static const char *dict_value(const char *hdr, const char *key)
{
    char pat[32];
    snprintf(pat, sizeof pat, "'%s'", key);
    const char *p = strstr(hdr, pat);
    if (!p) {
        snprintf(pat, sizeof pat, "\"%s\"", key);
        p = strstr(hdr, pat);
    }
    if (!p) return NULL;
    p += strlen(pat);
    while (isspace((unsigned char)*p)) p++;
    if (*p != ':') return NULL;
    p++;
    while (isspace((unsigned char)*p)) p++;
    return p;
}

static int parse_descr(const char *path, const char *v, sp_dtype *dt, sp_error *err)
{
    char q = *v;
    if (q != '\'' && q != '"') return sp_error_set(err, SP_E_FORMAT, "%s: npy header 'descr' is not a string", path);
    const char *end = strchr(v + 1, q);
    if (!end || end - v - 1 > 15) return sp_error_set(err, SP_E_FORMAT, "%s: npy header 'descr' is malformed", path);
    char d[16];
    memcpy(d, v + 1, (size_t)(end - v - 1));
    d[end - v - 1] = 0;
    if (d[0] == '>' && strcmp(d + 1, "u1") && strcmp(d + 1, "i1") && strcmp(d + 1, "b1"))
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: big-endian dtype '%s' is not supported", path, d);
    const char *t = (d[0] == '<' || d[0] == '|' || d[0] == '=' || d[0] == '>') ? d + 1 : d;
    static const struct { const char *s; sp_dtype t; } map[] = {
        {"f4", SP_DTYPE_F32}, {"f2", SP_DTYPE_F16}, {"u1", SP_DTYPE_U8}, {"b1", SP_DTYPE_U8},
        {"i4", SP_DTYPE_I32}, {"u2", SP_DTYPE_U16}, {"f8", SP_DTYPE_F64}, {"i8", SP_DTYPE_I64},
    };
    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
        if (!strcmp(t, map[i].s)) {
            *dt = map[i].t;
            return SP_OK;
        }
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "%s: npy dtype '%s' is not supported (float32/16/64, uint8/16, int32/64)", path, d);
}

static int parse_shape(const char *path, const char *v, sp_npy *a, sp_error *err)
{
    if (*v != '(') return sp_error_set(err, SP_E_FORMAT, "%s: npy header 'shape' is not a tuple", path);
    v++;
    a->ndim = 0;
    for (;;) {
        while (isspace((unsigned char)*v) || *v == ',') v++;
        if (*v == ')') break;
        if (!isdigit((unsigned char)*v))
            return sp_error_set(err, SP_E_FORMAT, "%s: npy header 'shape' has a bad entry near '%.12s'", path, v);
        if (a->ndim == 8) return sp_error_set(err, SP_E_UNSUPPORTED, "%s: npy array has more than 8 dimensions", path);
        char *end;
        unsigned long long d = strtoull(v, &end, 10);
        if (d > ((size_t)1 << 40))
            return sp_error_set(err, SP_E_FORMAT, "%s: npy dimension %llu is absurdly large", path, d);
        a->shape[a->ndim++] = (size_t)d;
        v = end;
    }
    return SP_OK;
}

/* Fortran order stores index (i0..in-1) at i0 + d0*(i1 + d1*(...)); we walk the C-order output
 * with an odometer and compute each source offset from Fortran strides. */
static void fortran_to_c(const unsigned char *src, unsigned char *dst, const sp_npy *a, size_t item)
{
    size_t count = sp_npy_count(a), fstride[8], idx[8] = {0};
    size_t s = 1;
    for (int k = 0; k < a->ndim; k++) {
        fstride[k] = s;
        s *= a->shape[k];
    }
    for (size_t i = 0; i < count; i++) {
        size_t off = 0;
        for (int k = 0; k < a->ndim; k++) off += idx[k] * fstride[k];
        memcpy(dst + i * item, src + off * item, item);
        for (int k = a->ndim - 1; k >= 0; k--) {
            if (++idx[k] < a->shape[k]) break;
            idx[k] = 0;
        }
    }
}

int sp_npy_read(const char *path, sp_npy *a, sp_error *err)
{
    memset(a, 0, sizeof *a);
    char *buf;
    size_t size;
    int rc = sp_read_file(path, &buf, &size, err);
    if (rc) return rc;
    rc = sp_npy_parse(buf, size, path, a, err);
    free(buf);
    return rc;
}

int sp_npy_parse(const void *data, size_t size, const char *path, sp_npy *a, sp_error *err)
{
    memset(a, 0, sizeof *a);
    int rc = SP_OK;
    const unsigned char *u = data;
    const char *buf = data;
    size_t hlen, hstart;
    if (size < 10 || memcmp(u, "\x93NUMPY", 6) != 0) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: not a .npy file (bad magic)", path);
        goto out;
    }
    if (u[6] == 1) {
        hlen = (size_t)u[8] | (size_t)u[9] << 8;
        hstart = 10;
    } else if (u[6] == 2 || u[6] == 3) {
        if (size < 12) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: truncated .npy header", path);
            goto out;
        }
        hlen = (size_t)u[8] | (size_t)u[9] << 8 | (size_t)u[10] << 16 | (size_t)u[11] << 24;
        hstart = 12;
    } else {
        rc = sp_error_set(err, SP_E_UNSUPPORTED, "%s: .npy version %d.%d is not supported", path, u[6], u[7]);
        goto out;
    }
    if (hlen > size - hstart) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: .npy header length %zu runs past the end of the file (%zu bytes)",
                          path, hlen, size);
        goto out;
    }
    char *hdr = malloc(hlen + 1);
    if (!hdr) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        goto out;
    }
    memcpy(hdr, buf + hstart, hlen);
    hdr[hlen] = 0;
    const char *dv = dict_value(hdr, "descr"), *fv = dict_value(hdr, "fortran_order"), *sv = dict_value(hdr, "shape");
    if (!dv || !fv || !sv) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: .npy header lacks '%s'", path, !dv ? "descr" : !fv ? "fortran_order" : "shape");
    } else if ((rc = parse_descr(path, dv, &a->dtype, err)) == 0 && (rc = parse_shape(path, sv, a, err)) == 0) {
        int fortran = strncmp(fv, "True", 4) == 0;
        if (!fortran && strncmp(fv, "False", 5) != 0)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: .npy 'fortran_order' is neither True nor False", path);
        size_t item = sp_dtype_size(a->dtype), count = 1, avail = size - hstart - hlen;
        for (int k = 0; k < a->ndim && !rc; k++) {
            if (a->shape[k] && count > SIZE_MAX / item / a->shape[k])
                rc = sp_error_set(err, SP_E_FORMAT, "%s: .npy shape overflows", path);
            count *= a->shape[k];
        }
        if (!rc && count * item > avail)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: .npy data truncated: shape needs %zu bytes, file has %zu",
                              path, count * item, avail);
        if (!rc) {
            const unsigned char *src = u + hstart + hlen;
            a->data = sp_alloc(count > 0 ? count * item : 1);
            if (!a->data)
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu bytes", path, count * item);
            else if (fortran && a->ndim > 1)
                fortran_to_c(src, a->data, a, item);
            else
                memcpy(a->data, src, count * item);
        }
    }
    free(hdr);
out:
    if (rc) sp_npy_free(a);
    return rc;
}

/* ---- writing ---------------------------------------------------------------------------------- */

int sp_npy_write(const char *path, sp_dtype dtype, int ndim, const size_t *shape, const void *data,
                 sp_error *err)
{
    static const char *descr[] = {"<f4", "<f2", "|u1", "<i4", "<u2", "<f8", "<i8"};
    if ((int)dtype < 0 || dtype > SP_DTYPE_I64)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: .npy has no dtype for %s", path, io_dtype_name(dtype));
    if (ndim < 0 || ndim > 8) return sp_error_set(err, SP_E_ARG, "%s: ndim %d is not in 0..8", path, ndim);
    char dict[512];
    int len = snprintf(dict, sizeof dict, "{'descr': '%s', 'fortran_order': False, 'shape': (", descr[dtype]);
    size_t count = 1;
    for (int k = 0; k < ndim; k++) {
        len += snprintf(dict + len, sizeof dict - (size_t)len, "%zu%s", shape[k], ndim == 1 ? "," : k + 1 < ndim ? ", " : "");
        count *= shape[k];
    }
    len += snprintf(dict + len, sizeof dict - (size_t)len, "), }");
    /* Version 1 header, padded with spaces so the data starts on a 64-byte boundary (NumPy >= 1.? does
     * the same, and readers that mmap rely on it). */
    size_t total = 10 + (size_t)len + 1;
    size_t padded = (total + 63) / 64 * 64;
    unsigned char head[640];
    memcpy(head, "\x93NUMPY\x01\x00", 8);
    size_t hlen = padded - 10;
    head[8] = (unsigned char)(hlen & 0xFF);
    head[9] = (unsigned char)(hlen >> 8);
    memcpy(head + 10, dict, (size_t)len);
    memset(head + 10 + len, ' ', padded - total);
    head[padded - 1] = '\n';
    char tmp[4200];
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) return err ? err->code : SP_E_IO;
    size_t nbytes = count * sp_dtype_size(dtype);
    fwrite(head, 1, padded, f);
    if (nbytes) fwrite(data, 1, nbytes, f);
    return io_tmp_commit(f, tmp, path, 1, err);
}

int sp_npy_to_f32(const sp_npy *a, float **out, sp_error *err)
{
    size_t n = sp_npy_count(a);
    float *o = sp_alloc(n ? n * sizeof(float) : sizeof(float));
    if (!o) return sp_error_set(err, SP_E_NOMEM, "npy: out of memory converting %zu values", n);
    const void *d = a->data;
    for (size_t i = 0; i < n; i++) {
        switch (a->dtype) {
        case SP_DTYPE_F32: o[i] = ((const float *)d)[i]; break;
        case SP_DTYPE_F16: o[i] = sp_half_to_float(((const uint16_t *)d)[i]); break;
        case SP_DTYPE_BF16: o[i] = sp_bf16_to_float(((const uint16_t *)d)[i]); break;
        case SP_DTYPE_U8: o[i] = ((const uint8_t *)d)[i]; break;
        case SP_DTYPE_U16: o[i] = ((const uint16_t *)d)[i]; break;
        case SP_DTYPE_I32: o[i] = (float)((const int32_t *)d)[i]; break;
        case SP_DTYPE_I64: o[i] = (float)((const int64_t *)d)[i]; break;
        case SP_DTYPE_F64: o[i] = (float)((const double *)d)[i]; break;
        }
    }
    *out = o;
    return SP_OK;
}
