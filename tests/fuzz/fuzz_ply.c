/* Splat PLY, binary and ascii (sp_ply_parse_splat): never a crash, a clear error, and a splat that
 * parses survives our binary writer and a re-read bit for bit. The custom mutator keeps the
 * header's vertex count consistent with the body (bytes / stride, or lines for ascii) most of
 * the time, so mutations of the properties and values reach the vertex decoder instead of
 * stopping at the size check. */
#include <ctype.h>

#include "fuzz_util.h"
#include "semsplat/io.h"

static void same_splat(const sp_splat *a, const sp_splat *b)
{
    FZ_ASSERT(a->n == b->n && a->sh_degree == b->sh_degree && a->feat_dim == b->feat_dim,
              "n/degree/dim changed in a round trip");
    size_t n = a->n, K = (size_t)sp_sh_coeffs(a->sh_degree), D = (size_t)a->feat_dim;
    if (!n) return;
    FZ_ASSERT(!memcmp(a->means, b->means, n * 3 * sizeof(float)), "means changed");
    FZ_ASSERT(!memcmp(a->quats, b->quats, n * 4 * sizeof(float)), "quats changed");
    FZ_ASSERT(!memcmp(a->log_scales, b->log_scales, n * 3 * sizeof(float)), "scales changed");
    FZ_ASSERT(!memcmp(a->opacity_logits, b->opacity_logits, n * sizeof(float)), "opacities changed");
    FZ_ASSERT(!memcmp(a->sh, b->sh, n * K * 3 * sizeof(float)), "SH changed");
    FZ_ASSERT(!D || !memcmp(a->features, b->features, n * D * sizeof(float)), "features changed");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sp_splat s, t;
    sp_error err = {0};
    int rc = sp_ply_parse_splat(data, size, "fuzz.ply", &s, &err);
    if (rc) {
        fz_check_error(rc, &err, "sp_ply_parse_splat");
        FZ_ASSERT(!s.means && !s.n, "a failed parse left a splat behind");
        return 0;
    }
    char path[1024];
    fz_path("rt.ply", path);
    rc = sp_ply_write_splat(path, &s, &err);
    FZ_ASSERT(rc == 0, "a splat that parsed does not write back: %s", err.msg);
    rc = sp_ply_read_splat(path, &t, &err);
    FZ_ASSERT(rc == 0, "what we wrote does not read back: %s", err.msg);
    same_splat(&s, &t);
    sp_splat_free(&t);
    sp_splat_free(&s);
    return 0;
}

/* ---- structure-aware mutation ------------------------------------------------------------------ */

static int type_size(const char *t)
{
    static const struct { const char *name; int size; } T[] = {
        {"char", 1}, {"int8", 1}, {"uchar", 1}, {"uint8", 1}, {"short", 2}, {"int16", 2}, {"ushort", 2},
        {"uint16", 2}, {"int", 4}, {"int32", 4}, {"uint", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4},
        {"double", 8}, {"float64", 8}};
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++)
        if (!strcmp(t, T[i].name)) return T[i].size;
    return 0;
}

/* Rewrites "element vertex N" so N matches the body: binary = body bytes / vertex stride, ascii =
 * non-blank lines. Only when the vertex element is the first one (what our writer and 3DGS make). */
static size_t fix_count(uint8_t *data, size_t size, size_t max)
{
    const uint8_t *end = NULL;
    for (size_t i = 0; i + 11 <= size; i++)
        if (!memcmp(data + i, "end_header\n", 11)) {
            end = data + i + 11;
            break;
        }
    if (!end) return size;
    size_t hsize = (size_t)(end - data), body = size - hsize;
    char *hdr = malloc(hsize + 1);
    if (!hdr) return size;
    memcpy(hdr, data, hsize);
    hdr[hsize] = 0;
    int ascii = strstr(hdr, "format ascii") != NULL, in_vertex = 0, elements = 0, stride = 0;
    char *count_at = NULL, *count_end = NULL;
    for (char *line = hdr; line && *line;) {
        char *nl = strchr(line, '\n');
        char kw[16], a[32], b[64];
        int nt = sscanf(line, "%15s %31s %63s", kw, a, b);
        if (nt >= 3 && !strcmp(kw, "element")) {
            in_vertex = !strcmp(a, "vertex") && elements == 0;
            elements++;
            if (in_vertex) {
                count_at = strstr(line, b);
                count_end = count_at ? count_at + strlen(b) : NULL;
            }
        } else if (nt >= 3 && !strcmp(kw, "property") && in_vertex) {
            stride += type_size(a);
        }
        line = nl ? nl + 1 : NULL;
    }
    size_t n = 0;
    if (ascii) {
        int blank = 1;
        for (size_t i = 0; i < body; i++) {
            if (end[i] == '\n') n += !blank, blank = 1;
            else if (!isspace(end[i])) blank = 0;
        }
        n += !blank;
    } else if (stride) {
        n = body / (size_t)stride;
    }
    size_t out = size;
    if (count_at && count_end && (ascii || stride)) {
        char num[32];
        int nl = snprintf(num, sizeof num, "%zu", n);
        size_t before = (size_t)(count_at - hdr), old = (size_t)(count_end - count_at);
        size_t total = size - old + (size_t)nl;
        if (total <= max) {
            memmove(data + before + nl, data + before + old, size - before - old);
            memcpy(data + before, num, (size_t)nl);
            out = total;
            /* binary: drop a partial trailing record so the size check passes */
            if (!ascii) out -= (body - n * (size_t)stride);
        }
    }
    free(hdr);
    return out;
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    size = LLVMFuzzerMutate(data, size, max_size);
    if (seed % 5 == 0) return size; /* sometimes leave the counts as mutated */
    return fix_count(data, size, max_size);
}
