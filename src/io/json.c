/* JSON files through cJSON: parse errors say where (line and column), writes are atomic. Used for
 * configs, manifests and the safetensors header. */
#include "io_internal.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>

/* 1-based line and column of byte offset `at` in text. */
static void line_col(const char *text, size_t at, int *line, int *col)
{
    *line = 1;
    *col = 1;
    for (size_t i = 0; i < at && text[i]; i++) {
        if (text[i] == '\n') {
            (*line)++;
            *col = 1;
        } else {
            (*col)++;
        }
    }
}

/* Parses text[0..size] (text[size] == 0). */
static int parse_terminated(const char *text, size_t size, const char *path, cJSON **out, sp_error *err)
{
    const char *nul = memchr(text, 0, size);
    if (nul) {
        int line, col;
        line_col(text, (size_t)(nul - text), &line, &col);
        return sp_error_set(err, SP_E_FORMAT, "%s:%d:%d: invalid JSON: a NUL byte (a binary file?)", path, line, col);
    }
    const char *end = NULL;
    cJSON *json = cJSON_ParseWithLengthOpts(text, size + 1, &end, 1) /* + the NUL */;
    if (!json) {
        int line, col;
        size_t at = end && end >= text && end <= text + size ? (size_t)(end - text) : 0;
        line_col(text, at, &line, &col);
        return sp_error_set(err, SP_E_FORMAT, "%s:%d:%d: invalid JSON near '%.20s'", path, line, col,
                            at < size ? text + at : "<end of file>");
    }
    *out = json;
    return SP_OK;
}

int sp_json_read_file(const char *path, struct cJSON **out, sp_error *err)
{
    *out = NULL;
    char *text;
    size_t size;
    int rc = sp_read_file(path, &text, &size, err);
    if (rc) return rc;
    rc = parse_terminated(text, size, path, out, err);
    free(text);
    return rc;
}

int sp_json_parse(const char *text, size_t size, const char *name, struct cJSON **out, sp_error *err)
{
    *out = NULL;
    char *copy = malloc(size + 1);
    if (!copy) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu bytes", name, size);
    if (size) memcpy(copy, text, size);
    copy[size] = 0;
    int rc = parse_terminated(copy, size, name, out, err);
    free(copy);
    return rc;
}

int sp_json_int(const struct cJSON *v, long lo, long hi, long *out)
{
    /* Range first: converting a double outside long's range is undefined behaviour. */
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= (double)lo) || !(v->valuedouble <= (double)hi)) return -1;
    double d = v->valuedouble;
    if (d != floor(d)) return -1;
    *out = (long)d;
    return 0;
}

struct cJSON *sp_json_number_exact(double d)
{
    if (!isfinite(d)) return NULL;
    char buf[40];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, d);
        if (strtod(buf, NULL) == d) break;
    }
    return cJSON_CreateRaw(buf);
}

int sp_json_write_file(const char *path, const struct cJSON *json, sp_error *err)
{
    char *text = cJSON_Print(json);
    if (!text) return sp_error_set(err, SP_E_NOMEM, "%s: cannot serialise JSON", path);
    size_t n = strlen(text);
    /* A trailing newline, as text tools expect. */
    char *t2 = realloc(text, n + 2);
    if (!t2) {
        cJSON_free(text);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    }
    t2[n] = '\n';
    t2[n + 1] = 0;
    int rc = sp_write_file_atomic(path, t2, n + 1, err);
    free(t2);
    return rc;
}
