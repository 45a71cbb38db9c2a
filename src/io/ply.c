/* Splat PLY: the Gaussian layout written by the original 3DGS code (save_ply) and by gsplat's
 * export: x y z nx ny nz f_dc_0..2 f_rest_* opacity scale_0..2 rot_0..3, plus our f_sem_0..d-1.
 * f_rest is channel-major (all red coefficients, then green, then blue), so
 * f_rest[c*(K-1) + (k-1)] is sh[i][k][c]. Opacity is a logit, scales are logs, rot is (w,x,y,z). */
#include "io_internal.h"

#include <ctype.h>
#include <float.h>
#include <errno.h>
#include <stdlib.h>
#include <sys/stat.h>

#define PLY_MAX_PROPS 4200 /* 62 Gaussian fields + up to 4096 features + a few extras */
#define PLY_CHUNK 4096     /* vertices decoded per read */

typedef enum { T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 } ply_type;
static const struct {
    const char *name, *alias;
    int size;
} types[] = {{"char", "int8", 1},   {"uchar", "uint8", 1}, {"short", "int16", 2}, {"ushort", "uint16", 2},
             {"int", "int32", 4},   {"uint", "uint32", 4}, {"float", "float32", 4}, {"double", "float64", 8}};

/* Where a vertex property goes in sp_splat. */
typedef enum { D_IGNORE, D_MEAN, D_DC, D_REST, D_OPACITY, D_SCALE, D_ROT, D_SEM } ply_dest;

typedef struct {
    char name[64];
    ply_type type;
    int offset; /* byte offset within a binary vertex record */
    ply_dest dest;
    int index;
} ply_prop;

typedef struct {
    const char *path;
    int ascii;
    size_t n_vertex;
    size_t skip_bytes;  /* binary: bytes of scalar-only elements before the vertex element */
    size_t skip_lines;  /* ascii: lines of elements before the vertex element */
    size_t header_size; /* bytes up to and including "end_header\n" */
    size_t header_lines;
    int stride;
    int n_props;
    ply_prop *props;
    int n_rest, n_sem;
} ply_header;

static double read_value(const unsigned char *p, ply_type t)
{
    switch (t) {
    case T_I8: return (double)*(const int8_t *)p;
    case T_U8: return (double)*p;
    case T_I16: { int16_t v; memcpy(&v, p, 2); return v; }
    case T_U16: { uint16_t v; memcpy(&v, p, 2); return v; }
    case T_I32: { int32_t v; memcpy(&v, p, 4); return v; }
    case T_U32: { uint32_t v; memcpy(&v, p, 4); return v; }
    case T_F32: { float v; memcpy(&v, p, 4); return v; }
    case T_F64: { double v; memcpy(&v, p, 8); return v; }
    }
    return 0;
}

/* Parses "prefix<digits>" into the index, or returns -1. */
static int suffix_index(const char *name, const char *prefix)
{
    size_t n = strlen(prefix);
    if (strncmp(name, prefix, n) != 0 || !isdigit((unsigned char)name[n])) return -1;
    char *end;
    long v = strtol(name + n, &end, 10);
    return *end || v > 100000 ? -1 : (int)v;
}

static void classify(ply_prop *p)
{
    static const char *xyz[] = {"x", "y", "z"};
    p->dest = D_IGNORE;
    for (int k = 0; k < 3; k++)
        if (!strcmp(p->name, xyz[k])) p->dest = D_MEAN, p->index = k;
    if (!strcmp(p->name, "opacity")) p->dest = D_OPACITY, p->index = 0;
    int k;
    if ((k = suffix_index(p->name, "f_dc_")) >= 0 && k < 3) p->dest = D_DC, p->index = k;
    else if ((k = suffix_index(p->name, "f_rest_")) >= 0) p->dest = D_REST, p->index = k;
    else if ((k = suffix_index(p->name, "scale_")) >= 0 && k < 3) p->dest = D_SCALE, p->index = k;
    else if ((k = suffix_index(p->name, "rot_")) >= 0 && k < 4) p->dest = D_ROT, p->index = k;
    else if ((k = suffix_index(p->name, "f_sem_")) >= 0) p->dest = D_SEM, p->index = k;
}

/* Checks that every required field is present exactly once and the numbered families (f_rest_*,
 * f_sem_*) are contiguous from 0. */
static int check_props(ply_header *h, sp_error *err)
{
    static const struct { ply_dest d; int count; const char *fmt; } req[] = {
        {D_MEAN, 3, "xyz"}, {D_DC, 3, "f_dc_%d"}, {D_OPACITY, 1, "opacity"}, {D_SCALE, 3, "scale_%d"}, {D_ROT, 4, "rot_%d"}};
    static const char *xyz[] = {"x", "y", "z"};
    h->n_rest = h->n_sem = 0;
    for (int i = 0; i < h->n_props; i++) {
        if (h->props[i].dest == D_REST) h->n_rest++;
        if (h->props[i].dest == D_SEM) h->n_sem++;
    }
    for (size_t r = 0; r < sizeof req / sizeof req[0]; r++) {
        for (int k = 0; k < req[r].count; k++) {
            int found = 0;
            for (int i = 0; i < h->n_props; i++) found += h->props[i].dest == req[r].d && h->props[i].index == k;
            char name[32];
            if (req[r].d == D_MEAN) snprintf(name, sizeof name, "%s", xyz[k]);
            else if (req[r].d == D_OPACITY) snprintf(name, sizeof name, "opacity");
            else snprintf(name, sizeof name, req[r].fmt, k);
            if (found == 0)
                return sp_error_set(err, SP_E_FORMAT, "%s: vertex property '%s' is missing (not a 3DGS/gsplat splat PLY?)",
                                    h->path, name);
            if (found > 1) return sp_error_set(err, SP_E_FORMAT, "%s: vertex property '%s' appears twice", h->path, name);
        }
    }
    if (h->n_rest != 0 && h->n_rest != 9 && h->n_rest != 24 && h->n_rest != 45)
        return sp_error_set(err, SP_E_FORMAT,
                            "%s: %d f_rest_* properties; SH degree 0-3 needs 0, 9, 24 or 45", h->path, h->n_rest);
    if (h->n_sem > 4096) return sp_error_set(err, SP_E_UNSUPPORTED, "%s: %d f_sem_* features (at most 4096)", h->path, h->n_sem);
    /* Each index of a family 0..n-1 exactly once: with n members all < n and no repeats. */
    for (int fam = 0; fam < 2; fam++) {
        ply_dest d = fam ? D_SEM : D_REST;
        int n = fam ? h->n_sem : h->n_rest;
        const char *pre = fam ? "f_sem_" : "f_rest_";
        char *seen = calloc((size_t)n + 1, 1);
        if (!seen) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", h->path);
        for (int i = 0; i < h->n_props; i++) {
            if (h->props[i].dest != d) continue;
            int k = h->props[i].index;
            if (k >= n || seen[k]) {
                free(seen);
                return sp_error_set(err, SP_E_FORMAT, "%s: property %s%d is out of sequence (%d %s* properties)",
                                    h->path, pre, k, n, pre);
            }
            seen[k] = 1;
        }
        free(seen);
    }
    return SP_OK;
}

/* Reads the header from f (positioned at 0). */
static int parse_header(FILE *f, ply_header *h, sp_error *err)
{
    char line[1024];
    int lineno = 0, in_vertex = 0, seen_vertex = 0, seen_format = 0;
    size_t elem_count = 0, elem_stride = 0;
    int elem_has_list = 0;
    const char *path = h->path;
    if (!fgets(line, sizeof line, f) || strncmp(line, "ply", 3) != 0 || (line[3] != '\n' && line[3] != '\r'))
        return sp_error_set(err, SP_E_FORMAT, "%s: not a PLY file (no 'ply' magic line)", path);
    lineno = 1;
    h->props = calloc(PLY_MAX_PROPS, sizeof *h->props);
    if (!h->props) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    for (;;) {
        if (!fgets(line, sizeof line, f))
            return sp_error_set(err, SP_E_FORMAT, "%s: header ends at line %d without 'end_header'", path, lineno);
        lineno++;
        size_t len = strlen(line);
        if (len == sizeof line - 1 && line[len - 1] != '\n')
            return sp_error_set(err, SP_E_FORMAT, "%s: header line %d is too long", path, lineno);
        while (len && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = 0;
        char kw[32] = "", a[64] = "", b[64] = "", c[64] = "", extra[8] = "";
        int nt = sscanf(line, "%31s %63s %63s %63s %7s", kw, a, b, c, extra);
        if (nt <= 0) continue;
        if (!strcmp(kw, "comment") || !strcmp(kw, "obj_info")) continue;
        if (!strcmp(kw, "format")) {
            if (nt < 3) return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: bad format line", path, lineno);
            if (!strcmp(a, "ascii")) h->ascii = 1;
            else if (!strcmp(a, "binary_little_endian")) h->ascii = 0;
            else if (!strcmp(a, "binary_big_endian"))
                return sp_error_set(err, SP_E_UNSUPPORTED, "%s: binary_big_endian PLY is not supported", path);
            else return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: unknown format '%s'", path, lineno, a);
            seen_format = 1;
        } else if (!strcmp(kw, "element")) {
            if (!seen_vertex && !in_vertex && elem_count) {
                if (elem_has_list)
                    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: a list element before 'vertex' is not supported", path);
                /* Bounded by the file size in check_count; here only kept from wrapping. */
                if (elem_count > SIZE_MAX - h->skip_lines ||
                    (elem_stride && elem_count > (SIZE_MAX - h->skip_bytes) / elem_stride))
                    return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: element counts overflow", path, lineno);
                h->skip_lines += elem_count;
                h->skip_bytes += elem_count * elem_stride;
            }
            if (in_vertex) seen_vertex = 1;
            in_vertex = 0;
            elem_stride = 0;
            elem_has_list = 0;
            char *end;
            errno = 0;
            unsigned long long n = nt >= 3 ? strtoull(b, &end, 10) : 0;
            if (nt < 3 || !isdigit((unsigned char)b[0]) || *end || errno)
                return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: bad element line '%s'", path, lineno, line);
            elem_count = (size_t)n;
            if (!strcmp(a, "vertex")) {
                if (seen_vertex) return sp_error_set(err, SP_E_FORMAT, "%s: two vertex elements", path);
                in_vertex = 1;
                h->n_vertex = (size_t)n;
            }
        } else if (!strcmp(kw, "property")) {
            if (!strcmp(a, "list")) {
                if (in_vertex) return sp_error_set(err, SP_E_UNSUPPORTED, "%s: list property '%s' in vertex", path, c);
                elem_has_list = 1;
                continue;
            }
            int t = -1;
            for (int k = 0; k < 8; k++)
                if (!strcmp(a, types[k].name) || !strcmp(a, types[k].alias)) t = k;
            if (t < 0 || nt != 3)
                return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: bad property line '%s'", path, lineno, line);
            if (!in_vertex) {
                elem_stride += (size_t)types[t].size;
                continue;
            }
            if (h->n_props == PLY_MAX_PROPS)
                return sp_error_set(err, SP_E_UNSUPPORTED, "%s: more than %d vertex properties", path, PLY_MAX_PROPS);
            ply_prop *p = &h->props[h->n_props++];
            snprintf(p->name, sizeof p->name, "%s", b);
            p->type = (ply_type)t;
            p->offset = h->stride;
            h->stride += types[t].size;
            classify(p);
            for (int i = 0; i < h->n_props - 1; i++)
                if (!strcmp(h->props[i].name, p->name))
                    return sp_error_set(err, SP_E_FORMAT, "%s: vertex property '%s' appears twice", path, p->name);
        } else if (!strcmp(kw, "end_header")) {
            break;
        } else {
            return sp_error_set(err, SP_E_FORMAT, "%s: header line %d: unknown keyword '%s'", path, lineno, kw);
        }
    }
    if (!seen_format) return sp_error_set(err, SP_E_FORMAT, "%s: header has no format line", path);
    if (!in_vertex && !seen_vertex) return sp_error_set(err, SP_E_FORMAT, "%s: no 'element vertex' in the header", path);
    long pos = ftell(f);
    if (pos < 0) return sp_error_set(err, SP_E_IO, "%s: cannot tell position", path);
    h->header_size = (size_t)pos;
    h->header_lines = (size_t)lineno;
    return check_props(h, err);
}

/* Stores one decoded vertex (values[] in property order) into s at index i. */
static int store_vertex(const ply_header *h, const double *values, sp_splat *s, size_t i, sp_error *err)
{
    size_t K = (size_t)sp_sh_coeffs(s->sh_degree);
    int rest_per_channel = (int)K - 1;
    for (int j = 0; j < h->n_props; j++) {
        const ply_prop *p = &h->props[j];
        if (p->dest == D_IGNORE) continue;
        double v = values[j];
        if (!isfinite(v))
            return sp_error_set(err, SP_E_NUMERIC, "%s: vertex %zu has a non-finite %s (%g)", h->path, i, p->name, v);
        /* a double beyond float's range would become inf in the splat */
        if (!(fabs(v) <= FLT_MAX))
            return sp_error_set(err, SP_E_NUMERIC, "%s: vertex %zu has %s = %g, beyond float range", h->path, i,
                                p->name, v);
        float fv = (float)v;
        switch (p->dest) {
        case D_MEAN: s->means[i * 3 + p->index] = fv; break;
        case D_DC: s->sh[i * K * 3 + p->index] = fv; break;
        case D_REST: {
            int c = p->index / rest_per_channel, k = p->index % rest_per_channel + 1;
            s->sh[(i * K + (size_t)k) * 3 + c] = fv;
            break;
        }
        case D_OPACITY: s->opacity_logits[i] = fv; break;
        case D_SCALE: s->log_scales[i * 3 + p->index] = fv; break;
        case D_ROT: s->quats[i * 4 + p->index] = fv; break;
        case D_SEM: s->features[i * (size_t)s->feat_dim + p->index] = fv; break;
        case D_IGNORE: break;
        }
    }
    return SP_OK;
}

/* Bounds the vertex count (and what precedes the vertices) by the bytes after the header,
 * before anything is allocated. */
static int check_count(size_t file_size, const ply_header *h, sp_error *err)
{
    size_t after = file_size > h->header_size ? file_size - h->header_size : 0;
    if (!h->ascii && h->skip_bytes > after)
        return sp_error_set(err, SP_E_FORMAT,
                            "%s: the elements before 'vertex' take %zu bytes but only %zu follow the header "
                            "(truncated?)", h->path, h->skip_bytes, after);
    /* ascii: every line of an element before the vertices takes at least a digit and a newline. */
    if (h->ascii && h->skip_lines > after / 2)
        return sp_error_set(err, SP_E_FORMAT,
                            "%s: the elements before 'vertex' have %zu lines but only %zu bytes follow the header "
                            "(truncated?)", h->path, h->skip_lines, after);
    size_t avail = h->ascii ? after - 2 * h->skip_lines : after - h->skip_bytes;
    /* ascii: each value needs at least a digit and a separator. */
    size_t min_record = h->ascii ? 2 * (size_t)h->n_props : (size_t)h->stride;
    if (min_record == 0 || h->n_vertex > avail / min_record)
        return sp_error_set(err, SP_E_FORMAT,
                            "%s: header says %zu vertices (%zu bytes each at least) but only %zu bytes follow the "
                            "header (truncated?)", h->path, h->n_vertex, min_record, avail);
    return SP_OK;
}

static int read_binary(FILE *f, const ply_header *h, sp_splat *s, double *values, sp_error *err)
{
    size_t start = h->header_size + h->skip_bytes;
    if (fseek(f, (long)start, SEEK_SET) != 0) return sp_error_set(err, SP_E_IO, "%s: cannot seek", h->path);
    unsigned char *buf = malloc((size_t)h->stride * PLY_CHUNK);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", h->path);
    int rc = SP_OK;
    for (size_t i0 = 0; !rc && i0 < h->n_vertex; i0 += PLY_CHUNK) {
        size_t n = h->n_vertex - i0 < PLY_CHUNK ? h->n_vertex - i0 : PLY_CHUNK;
        if (fread(buf, (size_t)h->stride, n, f) != n) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: truncated vertex data near vertex %zu", h->path, i0);
            break;
        }
        for (size_t r = 0; !rc && r < n; r++) {
            for (int j = 0; j < h->n_props; j++)
                values[j] = read_value(buf + r * (size_t)h->stride + h->props[j].offset, h->props[j].type);
            rc = store_vertex(h, values, s, i0 + r, err);
        }
    }
    free(buf);
    return rc;
}

static int read_ascii(FILE *f, const ply_header *h, sp_splat *s, double *values, sp_error *err)
{
    size_t cap = 1 << 16;
    char *line = malloc(cap);
    if (!line) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", h->path);
    int rc = SP_OK;
    size_t lineno = 0;
    for (size_t i = 0; !rc && i < h->n_vertex + h->skip_lines;) {
        /* getline-like read of one whole line into a growing buffer. */
        size_t len = 0;
        int ch;
        while ((ch = fgetc(f)) != EOF && ch != '\n') {
            if (len + 1 >= cap) {
                char *nl = realloc(line, cap * 2);
                if (!nl) {
                    rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", h->path);
                    break;
                }
                line = nl;
                cap *= 2;
            }
            line[len++] = (char)ch;
        }
        if (rc) break;
        line[len] = 0;
        lineno++;
        if (ch == EOF && len == 0) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: truncated: %zu of %zu vertices present", h->path,
                              i > h->skip_lines ? i - h->skip_lines : 0, h->n_vertex);
            break;
        }
        char *p = line;
        while (isspace((unsigned char)*p)) p++;
        if (!*p) continue; /* blank lines are not records */
        if (i++ < h->skip_lines) continue;
        int j = 0;
        for (; j < h->n_props; j++) {
            char *end;
            values[j] = strtod(p, &end);
            if (end == p) break;
            p = end;
        }
        while (isspace((unsigned char)*p)) p++;
        if (j < h->n_props || *p)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: line %zu (vertex %zu): expected %d numbers%s%.40s%s", h->path,
                              h->header_lines + lineno, i - 1 - h->skip_lines, h->n_props, *p ? ", found '" : "",
                              p, *p ? "'" : "");
        else
            rc = store_vertex(h, values, s, i - 1 - h->skip_lines, err);
    }
    free(line);
    return rc;
}

/* Reads a splat from f (positioned at 0) holding file_size bytes; path names it in messages. */
static int read_splat(FILE *f, size_t file_size, const char *path, sp_splat *s, sp_error *err)
{
    ply_header h;
    memset(&h, 0, sizeof h);
    h.path = path;
    int rc = parse_header(f, &h, err);
    if (!rc) rc = check_count(file_size, &h, err);
    double *values = NULL;
    if (!rc) {
        int degree = h.n_rest == 0 ? 0 : h.n_rest == 9 ? 1 : h.n_rest == 24 ? 2 : 3;
        rc = sp_splat_alloc(s, h.n_vertex, degree, h.n_sem, err);
        if (rc) sp_error_prefix(err, "%s: ", path);
    }
    if (!rc && !(values = malloc(sizeof(double) * (size_t)h.n_props)))
        rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    if (!rc) rc = h.ascii ? read_ascii(f, &h, s, values, err) : read_binary(f, &h, s, values, err);
    free(values);
    free(h.props);
    if (rc) sp_splat_free(s);
    return rc;
}

int sp_ply_read_splat(const char *path, sp_splat *s, sp_error *err)
{
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "rb");
    if (!f) return sp_error_set(err, SP_E_IO, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    int rc = fstat(fileno(f), &st) != 0 ? sp_error_set(err, SP_E_IO, "%s: cannot stat: %s", path, strerror(errno))
                                        : read_splat(f, (size_t)st.st_size, path, s, err);
    fclose(f);
    return rc;
}

int sp_ply_parse_splat(const void *data, size_t size, const char *name, sp_splat *s, sp_error *err)
{
    memset(s, 0, sizeof *s);
    FILE *f = io_memstream(data, size, name, "a PLY file", err);
    if (!f) return err ? err->code : SP_E_FORMAT;
    int rc = read_splat(f, size, name, s, err);
    fclose(f);
    return rc;
}

int sp_ply_write_splat(const char *path, const sp_splat *s, sp_error *err)
{
    if (s->sh_degree < 0 || s->sh_degree > 3 || s->feat_dim < 0)
        return sp_error_set(err, SP_E_ARG, "%s: splat has SH degree %d, feature dim %d", path, s->sh_degree, s->feat_dim);
    int rc = sp_splat_check_finite(s, err);
    if (rc) return sp_error_prefix(err, "%s: not writing: ", path);
    char tmp[4200];
    FILE *f = io_tmp_open(path, tmp, sizeof tmp, err);
    if (!f) return err ? err->code : SP_E_IO;
    size_t K = (size_t)sp_sh_coeffs(s->sh_degree), n_rest = 3 * (K - 1), D = (size_t)s->feat_dim;
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment written by semsplat\nelement vertex %zu\n", s->n);
    const char *fixed[] = {"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"};
    for (int k = 0; k < 9; k++) fprintf(f, "property float %s\n", fixed[k]);
    for (size_t k = 0; k < n_rest; k++) fprintf(f, "property float f_rest_%zu\n", k);
    fprintf(f, "property float opacity\n");
    for (int k = 0; k < 3; k++) fprintf(f, "property float scale_%d\n", k);
    for (int k = 0; k < 4; k++) fprintf(f, "property float rot_%d\n", k);
    for (size_t k = 0; k < D; k++) fprintf(f, "property float f_sem_%zu\n", k);
    fprintf(f, "end_header\n");
    size_t stride = 9 + n_rest + 1 + 3 + 4 + D;
    float *rec = malloc(stride * sizeof(float) * PLY_CHUNK);
    if (!rec) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        io_tmp_commit(f, tmp, path, 0, NULL);
        return rc;
    }
    for (size_t i0 = 0; i0 < s->n; i0 += PLY_CHUNK) {
        size_t n = s->n - i0 < PLY_CHUNK ? s->n - i0 : PLY_CHUNK;
        for (size_t r = 0; r < n; r++) {
            size_t i = i0 + r;
            float *o = rec + r * stride;
            const float *sh = s->sh + i * K * 3;
            memcpy(o, s->means + i * 3, 3 * sizeof(float));
            o[3] = o[4] = o[5] = 0.0f; /* normals: unused by splats, zero as 3DGS writes them */
            memcpy(o + 6, sh, 3 * sizeof(float));
            for (size_t c = 0; c < 3; c++)
                for (size_t k = 1; k < K; k++) o[9 + c * (K - 1) + (k - 1)] = sh[k * 3 + c];
            float *t = o + 9 + n_rest;
            t[0] = s->opacity_logits[i];
            memcpy(t + 1, s->log_scales + i * 3, 3 * sizeof(float));
            memcpy(t + 4, s->quats + i * 4, 4 * sizeof(float));
            if (D) memcpy(t + 8, s->features + i * D, D * sizeof(float));
        }
        fwrite(rec, sizeof(float) * stride, n, f);
    }
    free(rec);
    return io_tmp_commit(f, tmp, path, 1, err);
}
