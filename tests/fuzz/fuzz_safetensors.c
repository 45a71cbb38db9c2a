/* safetensors (sp_safetensors_parse): never a crash, a clear error, every tensor of a file that
 * parses lies inside the data, and the file survives our writer and a re-read bit for bit. The
 * custom mutator mutates the JSON header or the data separately and re-frames them with the
 * right header length; half the time it also re-tiles data_offsets from each tensor's dtype and
 * shape, so mutations of names, dtypes and shapes reach the checks past the offsets. */
#include <cjson/cJSON.h>

#include "fuzz_util.h"
#include "semsplat/io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sp_safetensors st, back;
    sp_error err = {0};
    int rc = sp_safetensors_parse(data, size, "fuzz.safetensors", &st, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_safetensors_parse");
        FZ_ASSERT(!st.tensors && !st.n, "a failed parse left tensors behind");
        return 0;
    }
    unsigned sum = 0;
    for (size_t i = 0; i < st.n; i++) {
        const sp_tensor_info *t = &st.tensors[i];
        const uint8_t *p = t->data;
        FZ_ASSERT(p >= data && p + t->nbytes <= data + size, "tensor '%s' points outside the file", t->name);
        for (size_t k = 0; k < t->nbytes; k++) sum += p[k];
        FZ_ASSERT(sp_safetensors_find(&st, t->name) == t, "tensor '%s' is not found by name", t->name);
    }
    (void)sum;
    char path[1024];
    fz_path("rt.safetensors", path);
    rc = sp_safetensors_write(path, st.tensors, st.n, &err);
    FZ_ASSERT(rc == 0, "what parsed does not write back: %s", err.msg);
    rc = sp_safetensors_open(path, &back, &err);
    FZ_ASSERT(rc == 0, "what we wrote does not read back: %s", err.msg);
    FZ_ASSERT(back.n == st.n, "tensor count changed");
    for (size_t i = 0; i < st.n; i++) {
        const sp_tensor_info *a = &st.tensors[i], *b = sp_safetensors_find(&back, a->name);
        FZ_ASSERT(b && b->dtype == a->dtype && b->ndim == a->ndim && !memcmp(b->shape, a->shape, sizeof a->shape) &&
                      b->nbytes == a->nbytes && !memcmp(a->data, b->data, a->nbytes),
                  "tensor '%s' changed in a round trip", a->name);
    }
    sp_safetensors_close(&back);
    sp_safetensors_close(&st);
    return 0;
}

/* ---- structure-aware mutation ------------------------------------------------------------------ */

static size_t dtype_bytes(const char *d)
{
    static const struct { const char *n; size_t s; } T[] = {{"F32", 4}, {"F16", 2}, {"BF16", 2}, {"I64", 8},
                                                            {"I32", 4}, {"U8", 1},  {"F64", 8},  {"U16", 2}};
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++)
        if (!strcmp(d, T[i].n)) return T[i].s;
    return 1;
}

/* Re-tiles data_offsets from dtype and shape; returns the new header (malloc'd) or NULL. */
static char *retile(const char *json, size_t len, size_t *total)
{
    cJSON *root = cJSON_ParseWithLength(json, len);
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return NULL;
    }
    size_t off = 0;
    for (cJSON *t = root->child; t; t = t->next) {
        cJSON *dt = cJSON_GetObjectItemCaseSensitive(t, "dtype"), *sh = cJSON_GetObjectItemCaseSensitive(t, "shape");
        if (!cJSON_IsObject(t) || !cJSON_IsString(dt) || !cJSON_IsArray(sh)) continue;
        double count = 1;
        cJSON *d;
        cJSON_ArrayForEach(d, sh) count *= cJSON_IsNumber(d) && d->valuedouble >= 0 ? d->valuedouble : 1;
        if (!(count <= 4096)) count = 4096; /* small files (and NaN from inf * 0): the shape check then fails */
        size_t nb = (size_t)count * dtype_bytes(dt->valuestring);
        cJSON *offs = cJSON_CreateArray();
        cJSON_AddItemToArray(offs, cJSON_CreateNumber((double)off));
        cJSON_AddItemToArray(offs, cJSON_CreateNumber((double)(off + nb)));
        if (cJSON_GetObjectItemCaseSensitive(t, "data_offsets"))
            cJSON_ReplaceItemInObjectCaseSensitive(t, "data_offsets", offs);
        else
            cJSON_AddItemToObject(t, "data_offsets", offs);
        off += nb;
    }
    char *out = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    *total = off;
    return out;
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    size_t hlen = size >= 8 ? (size_t)fz_get_u64(data) : 0;
    int framed = size >= 8 && hlen <= size - 8;
    const uint8_t *json = framed ? data + 8 : data, *tail = framed ? data + 8 + hlen : data + size;
    size_t jlen = framed ? hlen : size, tlen = (size_t)(data + size - tail);
    /* Mutate one of the two parts in a scratch copy with room to grow. */
    uint8_t *j = malloc(max_size + 1), *t = malloc(max_size + 1);
    if (!j || !t) {
        free(j), free(t);
        return LLVMFuzzerMutate(data, size, max_size);
    }
    memcpy(j, json, jlen);
    memcpy(t, tail, tlen);
    if (seed % 3) jlen = LLVMFuzzerMutate(j, jlen, max_size / 2);
    else tlen = LLVMFuzzerMutate(t, tlen, max_size / 2);
    char *fixed = NULL;
    size_t total = 0;
    if ((seed >> 2) & 1 && (fixed = retile((const char *)j, jlen, &total))) {
        size_t fl = strlen(fixed);
        if (fl <= max_size / 2 && total <= max_size / 2) {
            memcpy(j, fixed, fl);
            jlen = fl;
            if (total > tlen) memset(t + tlen, 0, total - tlen);
            tlen = total;
        }
        free(fixed);
    }
    size_t out = size;
    if (8 + jlen + tlen <= max_size) {
        fz_put_u64(data, jlen);
        memcpy(data + 8, j, jlen);
        memcpy(data + 8 + jlen, t, tlen);
        out = 8 + jlen + tlen;
    }
    free(j), free(t);
    return out;
}
