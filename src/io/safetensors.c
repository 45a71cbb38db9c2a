/* safetensors (Hugging Face): u64 little-endian header length N, N bytes of JSON
 * {"name": {"dtype", "shape", "data_offsets": [begin, end]}, "__metadata__": {...}}, then the byte
 * buffer. We mmap the file and check, as the reference implementation does, that every tensor's
 * size matches its shape and dtype and that the tensors tile the buffer exactly (no overlap, no
 * gap, nothing past the end). Tensor data pointers point into the mapping and need not be aligned. */
#include "io_internal.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#define ST_MAX_HEADER ((uint64_t)100 << 20) /* the format's own limit: 100 MB of JSON */

static const struct {
    const char *name;
    sp_dtype t;
} st_types[] = {{"F32", SP_DTYPE_F32}, {"F16", SP_DTYPE_F16}, {"BF16", SP_DTYPE_BF16}, {"I64", SP_DTYPE_I64},
                {"I32", SP_DTYPE_I32}, {"U8", SP_DTYPE_U8},   {"F64", SP_DTYPE_F64},   {"U16", SP_DTYPE_U16}};
#define N_ST_TYPES (sizeof st_types / sizeof st_types[0])

static const char *st_type_name(sp_dtype t)
{
    for (size_t i = 0; i < N_ST_TYPES; i++)
        if (st_types[i].t == t) return st_types[i].name;
    return NULL;
}

void sp_safetensors_close(sp_safetensors *st)
{
    if (!st) return;
    if (st->map) munmap(st->map, st->map_size);
    free(st->tensors);
    memset(st, 0, sizeof *st);
}

const sp_tensor_info *sp_safetensors_find(const sp_safetensors *st, const char *name)
{
    for (size_t i = 0; i < st->n; i++)
        if (!strcmp(st->tensors[i].name, name)) return &st->tensors[i];
    return NULL;
}

/* A JSON number that is a non-negative integer below 2^53 (above, a double no longer tells
 * 2^53 + 1 from 2^53: the file would be read as saying something else). */
static int json_size(const cJSON *v, size_t *out)
{
    if (!cJSON_IsNumber(v)) return -1;
    double d = v->valuedouble;
    if (!(d >= 0) || d >= 9007199254740992.0 || d != floor(d)) return -1;
    *out = (size_t)d;
    return 0;
}

static int parse_tensor(const char *path, const cJSON *item, sp_tensor_info *t, size_t offs[2], sp_error *err)
{
    const char *name = item->string;
    if (!name[0]) return sp_error_set(err, SP_E_FORMAT, "%s: a tensor has an empty name", path);
    if (strlen(name) >= sizeof t->name)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: tensor name '%.60s...' is longer than %zu bytes", path, name,
                            sizeof t->name - 1);
    snprintf(t->name, sizeof t->name, "%s", name);
    if (!cJSON_IsObject(item)) return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' entry is not an object", path, name);
    const cJSON *dt = cJSON_GetObjectItemCaseSensitive(item, "dtype");
    const cJSON *sh = cJSON_GetObjectItemCaseSensitive(item, "shape");
    const cJSON *of = cJSON_GetObjectItemCaseSensitive(item, "data_offsets");
    if (!cJSON_IsString(dt)) return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' has no string 'dtype'", path, name);
    if (!cJSON_IsArray(sh)) return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' has no 'shape' array", path, name);
    if (!cJSON_IsArray(of) || cJSON_GetArraySize(of) != 2)
        return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' has no 'data_offsets' [begin, end]", path, name);
    size_t i;
    for (i = 0; i < N_ST_TYPES; i++)
        if (!strcmp(dt->valuestring, st_types[i].name)) break;
    if (i == N_ST_TYPES)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: tensor '%s' has dtype %s (supported: F32 F16 BF16 F64 I64 I32 U16 U8)",
                            path, name, dt->valuestring);
    t->dtype = st_types[i].t;
    int nd = cJSON_GetArraySize(sh);
    if (nd > 8) return sp_error_set(err, SP_E_UNSUPPORTED, "%s: tensor '%s' has %d dimensions (at most 8)", path, name, nd);
    t->ndim = nd;
    size_t count = 1, item_size = sp_dtype_size(t->dtype);
    for (int k = 0; k < nd; k++) {
        if (json_size(cJSON_GetArrayItem(sh, k), &t->shape[k]))
            return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' shape entry %d is not a non-negative integer", path, name, k);
        if (t->shape[k] && count > SIZE_MAX / item_size / t->shape[k])
            return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' shape overflows", path, name);
        count *= t->shape[k];
    }
    if (json_size(cJSON_GetArrayItem(of, 0), &offs[0]) || json_size(cJSON_GetArrayItem(of, 1), &offs[1]))
        return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' data_offsets are not non-negative integers", path, name);
    if (offs[1] < offs[0])
        return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' data_offsets [%zu, %zu] end before they begin", path, name,
                            offs[0], offs[1]);
    t->nbytes = offs[1] - offs[0];
    if (t->nbytes != count * item_size)
        return sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' (%s, %zu values) needs %zu bytes but data_offsets span %zu",
                            path, name, dt->valuestring, count, count * item_size, t->nbytes);
    return SP_OK;
}

typedef struct {
    size_t begin, end, index;
} span;

static int cmp_span(const void *a, const void *b)
{
    const span *x = a, *y = b;
    return x->begin < y->begin ? -1 : x->begin > y->begin ? 1 : (x->end > y->end) - (x->end < y->end);
}

/* Parses the header of the bytes [u, u + size) into st->n / st->tensors (pointing into u). */
static int parse(const unsigned char *u, size_t size, const char *path, sp_safetensors *st, sp_error *err)
{
    if (size < 8) return sp_error_set(err, SP_E_FORMAT, "%s: %zu bytes is too short for a safetensors file", path, size);
    uint64_t hlen;
    memcpy(&hlen, u, 8);
    int rc = SP_OK;
    cJSON *json = NULL;
    span *spans = NULL;
    if (hlen > size - 8 || hlen > ST_MAX_HEADER) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: header length %llu exceeds the file (%zu bytes) or the 100 MB limit", path,
                          (unsigned long long)hlen, size);
        goto out;
    }
    if (hlen < 2 || u[8] != '{') {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: header is not a JSON object (not a safetensors file?)", path);
        goto out;
    }
    const char *end = NULL;
    json = cJSON_ParseWithLengthOpts((const char *)u + 8, (size_t)hlen, &end, 0);
    if (!json || !cJSON_IsObject(json)) {
        size_t at = end ? (size_t)(end - (const char *)u - 8) : 0;
        rc = sp_error_set(err, SP_E_FORMAT, "%s: header JSON is malformed near byte %zu", path, at);
        goto out;
    }
    size_t data_start = 8 + (size_t)hlen, data_size = size - data_start, n = 0;
    for (const cJSON *it = json->child; it; it = it->next) n += strcmp(it->string, "__metadata__") != 0;
    st->tensors = calloc(n ? n : 1, sizeof *st->tensors);
    spans = calloc(n ? n : 1, sizeof *spans);
    if (!st->tensors || !spans) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu tensors", path, n);
        goto out;
    }
    for (const cJSON *it = json->child; it && !rc; it = it->next) {
        if (!strcmp(it->string, "__metadata__")) continue;
        size_t offs[2] = {0, 0};
        rc = parse_tensor(path, it, &st->tensors[st->n], offs, err);
        if (rc) break;
        if (offs[1] > data_size) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' data_offsets [%zu, %zu] run past the data (%zu bytes; truncated?)",
                              path, it->string, offs[0], offs[1], data_size);
            break;
        }
        for (size_t k = 0; k < st->n; k++)
            if (!strcmp(st->tensors[k].name, it->string)) {
                rc = sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' appears twice", path, it->string);
                break;
            }
        st->tensors[st->n].data = u + data_start + offs[0];
        spans[st->n] = (span){offs[0], offs[1], st->n};
        st->n++;
    }
    if (rc) goto out;
    /* The tensors, in offset order, must tile [0, data_size) exactly. */
    qsort(spans, st->n, sizeof *spans, cmp_span);
    size_t pos = 0;
    for (size_t k = 0; k < st->n && !rc; k++) {
        const char *name = st->tensors[spans[k].index].name;
        if (spans[k].begin < pos)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: tensor '%s' [%zu, %zu] overlaps the previous tensor (ends at %zu)", path,
                              name, spans[k].begin, spans[k].end, pos);
        else if (spans[k].begin > pos)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: %zu unused bytes before tensor '%s' at offset %zu", path,
                              spans[k].begin - pos, name, spans[k].begin);
        pos = spans[k].end;
    }
    if (!rc && pos != data_size)
        rc = sp_error_set(err, SP_E_FORMAT, "%s: %zu bytes after the last tensor (data is %zu bytes, tensors end at %zu)",
                          path, data_size - pos, data_size, pos);
    if (!rc) {
        /* Keep tensors in file order so listings read like the file. */
        sp_tensor_info *sorted = calloc(st->n ? st->n : 1, sizeof *sorted);
        if (!sorted) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            goto out;
        }
        for (size_t k = 0; k < st->n; k++) sorted[k] = st->tensors[spans[k].index];
        free(st->tensors);
        st->tensors = sorted;
    }
out:
    free(spans);
    cJSON_Delete(json);
    return rc;
}

int sp_safetensors_open(const char *path, sp_safetensors *st, sp_error *err)
{
    memset(st, 0, sizeof *st);
    int fd = open(path, O_RDONLY);
    if (fd < 0) return sp_error_set(err, SP_E_IO, "%s: cannot open: %s", path, strerror(errno));
    struct stat sb;
    if (fstat(fd, &sb) != 0) {
        int e = errno;
        close(fd);
        return sp_error_set(err, SP_E_IO, "%s: cannot stat: %s", path, strerror(e));
    }
    size_t size = (size_t)sb.st_size;
    if (size < 8) {
        close(fd);
        return sp_error_set(err, SP_E_FORMAT, "%s: %zu bytes is too short for a safetensors file", path, size);
    }
    void *map = mmap(NULL, size, PROT_READ, MAP_PRIVATE, fd, 0);
    int e = errno;
    close(fd);
    if (map == MAP_FAILED) return sp_error_set(err, SP_E_IO, "%s: cannot mmap: %s", path, strerror(e));
    st->map = map;
    st->map_size = size;
    int rc = parse(map, size, path, st, err);
    if (rc) sp_safetensors_close(st);
    return rc;
}

int sp_safetensors_parse(const void *data, size_t size, const char *name, sp_safetensors *st, sp_error *err)
{
    memset(st, 0, sizeof *st);
    int rc = parse(data, size, name, st, err);
    if (rc) sp_safetensors_close(st);
    return rc;
}

/* An integer as its exact digits: cJSON prints numbers with 15 significant digits when that reads
 * back within a relative epsilon, so 9007199254740992 would come back as 9007199254740990. */
static cJSON *json_count(size_t v)
{
    char s[32];
    snprintf(s, sizeof s, "%zu", v);
    return cJSON_CreateRaw(s);
}

int sp_safetensors_write(const char *path, const sp_tensor_info *tensors, size_t n, sp_error *err)
{
    cJSON *root = cJSON_CreateObject();
    if (!root) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    int rc = SP_OK;
    size_t offset = 0;
    for (size_t i = 0; i < n && !rc; i++) {
        const sp_tensor_info *t = &tensors[i];
        const char *tn = st_type_name(t->dtype);
        size_t count = 1;
        for (int k = 0; k < t->ndim; k++) count *= t->shape[k];
        if (!tn) rc = sp_error_set(err, SP_E_UNSUPPORTED, "%s: tensor '%s' has an unsupported dtype", path, t->name);
        else if (t->ndim < 0 || t->ndim > 8) rc = sp_error_set(err, SP_E_ARG, "%s: tensor '%s' ndim %d", path, t->name, t->ndim);
        else if (!t->name[0] || !strcmp(t->name, "__metadata__"))
            rc = sp_error_set(err, SP_E_ARG, "%s: tensor %zu has an invalid name '%s'", path, i, t->name);
        else if (cJSON_GetObjectItemCaseSensitive(root, t->name))
            rc = sp_error_set(err, SP_E_ARG, "%s: tensor '%s' is given twice", path, t->name);
        else if (count && !t->data)
            rc = sp_error_set(err, SP_E_ARG, "%s: tensor '%s' has no data", path, t->name);
        if (rc) break;
        size_t nbytes = count * sp_dtype_size(t->dtype);
        cJSON *e = cJSON_CreateObject();
        cJSON *shape = cJSON_CreateArray();
        cJSON *offs = cJSON_CreateArray();
        if (!e || !shape || !offs) {
            cJSON_Delete(e), cJSON_Delete(shape), cJSON_Delete(offs);
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            break;
        }
        cJSON_AddStringToObject(e, "dtype", tn);
        for (int k = 0; k < t->ndim; k++) cJSON_AddItemToArray(shape, json_count(t->shape[k]));
        cJSON_AddItemToObject(e, "shape", shape);
        cJSON_AddItemToArray(offs, json_count(offset));
        cJSON_AddItemToArray(offs, json_count(offset + nbytes));
        cJSON_AddItemToObject(e, "data_offsets", offs);
        cJSON_AddItemToObject(root, t->name, e);
        offset += nbytes;
    }
    char *hdr = rc ? NULL : cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    if (rc) return rc;
    if (!hdr) return sp_error_set(err, SP_E_NOMEM, "%s: cannot serialise the header", path);
    /* Header padded with spaces to a multiple of 8 so the data is 8-byte aligned, as the
     * reference writer does. */
    size_t hl = strlen(hdr), padded = (hl + 7) / 8 * 8;
    uint64_t h64 = padded;
    char tmp[4200];
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) {
        free(hdr);
        return err ? err->code : SP_E_IO;
    }
    fwrite(&h64, 8, 1, f);
    fwrite(hdr, 1, hl, f);
    for (size_t k = hl; k < padded; k++) fputc(' ', f);
    free(hdr);
    for (size_t i = 0; i < n; i++) {
        size_t count = 1;
        for (int k = 0; k < tensors[i].ndim; k++) count *= tensors[i].shape[k];
        if (count) fwrite(tensors[i].data, sp_dtype_size(tensors[i].dtype), count, f);
    }
    return io_tmp_commit(f, tmp, path, 1, err);
}
