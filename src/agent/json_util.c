/* Small JSON and string helpers for the agent: exact parsing of untrusted bytes, cleaned copies of
 * strings that travel to a model or a terminal, growing buffers, rounded number arrays. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "agent_internal.h"

/* Whether the bytes stop inside a string or an open object/array: a body cut short. */
static int ends_open(const char *b, size_t n)
{
    int depth = 0, in_str = 0, esc = 0;
    for (size_t i = 0; i < n; i++) {
        char c = b[i];
        if (in_str) {
            if (esc) esc = 0;
            else if (c == '\\') esc = 1;
            else if (c == '"') in_str = 0;
        } else if (c == '"') {
            in_str = 1;
        } else if (c == '{' || c == '[') {
            depth++;
        } else if (c == '}' || c == ']') {
            if (--depth < 0) return 0;
        }
    }
    return in_str || depth > 0;
}

cJSON *agent_json_parse(const char *bytes, size_t size, const char *what, sp_error *err)
{
    if (!bytes || size == 0) {
        sp_error_set(err, SP_E_FORMAT, "%s: empty, expected JSON", what);
        return NULL;
    }
    const char *end = NULL;
    cJSON *j = cJSON_ParseWithLengthOpts(bytes, size, &end, 0);
    size_t at = end && end >= bytes && end <= bytes + size ? (size_t)(end - bytes) : 0;
    if (!j) {
        if (at >= size || ends_open(bytes, size))
            sp_error_set(err, SP_E_FORMAT, "%s: JSON ends early (truncated after %zu bytes?)", what,
                         size);
        else
            sp_error_set(err, SP_E_FORMAT, "%s: invalid JSON at byte %zu of %zu", what, at, size);
        return NULL;
    }
    while (at < size && (bytes[at] == ' ' || bytes[at] == '\t' || bytes[at] == '\n' ||
                         bytes[at] == '\r' || bytes[at] == 0))
        at++;
    if (at < size) {
        cJSON_Delete(j);
        sp_error_set(err, SP_E_FORMAT, "%s: unexpected bytes after the JSON value at byte %zu",
                     what, at);
        return NULL;
    }
    return j;
}

char *agent_clean_copy(char *out, size_t cap, const char *s)
{
    if (!cap) return out;
    const unsigned char *p = (const unsigned char *)(s ? s : "");
    size_t j = 0;
    for (; *p && j + 1 < cap; p++) out[j++] = (*p < 0x20 || *p == 0x7f) ? ' ' : (char)*p;
    if (*p) { /* cut short: do not end inside a UTF-8 sequence */
        while (j > 0 && ((unsigned char)out[j - 1] & 0xC0) == 0x80) j--;
        if (j > 0 && ((unsigned char)out[j - 1] & 0xC0) == 0xC0) j--;
    }
    out[j] = 0;
    return out;
}

char *agent_strndup(const char *s, size_t n)
{
    char *d = malloc(n + 1);
    if (!d) return NULL;
    if (n) memcpy(d, s, n);
    d[n] = 0;
    return d;
}

char *agent_strdup(const char *s) { return s ? agent_strndup(s, strlen(s)) : NULL; }

int agent_appendf(char **buf, size_t *len, size_t *cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    va_list ap2;
    va_copy(ap2, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) {
        va_end(ap2);
        return SP_E_ARG;
    }
    if (*len + (size_t)n + 1 > *cap) {
        size_t nc = *cap ? *cap : 256;
        while (nc < *len + (size_t)n + 1) nc *= 2;
        char *nb = realloc(*buf, nc);
        if (!nb) {
            va_end(ap2);
            return SP_E_NOMEM;
        }
        *buf = nb;
        *cap = nc;
    }
    vsnprintf(*buf + *len, *cap - *len, fmt, ap2);
    va_end(ap2);
    *len += (size_t)n;
    return SP_OK;
}

double agent_round4(double v)
{
    if (!isfinite(v)) return v;
    return round(v * 1e4) / 1e4;
}

cJSON *agent_json_numbers(const double *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++)
        cJSON_AddItemToArray(a, isfinite(v[i]) ? cJSON_CreateNumber(agent_round4(v[i]))
                                               : cJSON_CreateNull());
    return a;
}
