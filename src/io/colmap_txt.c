/* COLMAP text model files (cameras.txt, images.txt, points3D.txt) in the layout of COLMAP's
 * Write*Text: '#' comment lines, one line per camera / point, two lines per image (the pose line
 * and the POINTS2D line, which may be empty). Errors give file:line. Doubles are written with 17
 * significant digits so text round trips are exact. */
#include "colmap_internal.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>

/* ---- tokenising ------------------------------------------------------------------------------- */

typedef struct {
    char **tok;
    size_t n, cap;
} tokens;

/* Splits line (modified in place) on blanks. */
static int split(char *line, tokens *t)
{
    t->n = 0;
    for (char *p = line; *p;) {
        while (*p && isspace((unsigned char)*p)) *p++ = 0;
        if (!*p) break;
        if (t->n == t->cap) {
            size_t cap = t->cap ? t->cap * 2 : 64;
            char **nt = realloc(t->tok, cap * sizeof *nt);
            if (!nt) return -1;
            t->tok = nt;
            t->cap = cap;
        }
        t->tok[t->n++] = p;
        while (*p && !isspace((unsigned char)*p)) p++;
    }
    return 0;
}

/* A line reader over a NUL-terminated buffer that counts line numbers and strips '\r'. */
typedef struct {
    char *p;
    int line;
} lines;

static char *next_line(lines *L)
{
    if (!L->p || !*L->p) return NULL;
    char *s = L->p, *e = strchr(s, '\n');
    if (e) {
        *e = 0;
        L->p = e + 1;
    } else {
        L->p = s + strlen(s);
    }
    size_t n = strlen(s);
    if (n && s[n - 1] == '\r') s[n - 1] = 0;
    L->line++;
    return s;
}

static int is_data(const char *s)
{
    while (isspace((unsigned char)*s)) s++;
    return *s && *s != '#';
}

static int bad_field(const char *file, int line, const char *field, const char *tok, sp_error *err)
{
    return sp_error_set(err, SP_E_FORMAT, "%s:%d: bad %s '%s'", file, line, field, tok);
}

static int parse_f64(const char *file, int line, const char *field, const char *tok, double *v, sp_error *err)
{
    char *end;
    errno = 0;
    *v = strtod(tok, &end);
    if (end == tok || *end) return bad_field(file, line, field, tok, err);
    return SP_OK;
}

static int parse_u64(const char *file, int line, const char *field, const char *tok, uint64_t max, uint64_t *v,
                     sp_error *err)
{
    char *end;
    errno = 0;
    if (!isdigit((unsigned char)tok[0])) return bad_field(file, line, field, tok, err);
    unsigned long long x = strtoull(tok, &end, 10);
    if (*end || errno || x > max) return bad_field(file, line, field, tok, err);
    *v = x;
    return SP_OK;
}

static int parse_u32(const char *file, int line, const char *field, const char *tok, uint32_t *v, sp_error *err)
{
    uint64_t x;
    int rc = parse_u64(file, line, field, tok, UINT32_MAX, &x, err);
    if (!rc) *v = (uint32_t)x;
    return rc;
}

/* "file:line", the location the shared checks put in their messages. */
static const char *at(char *where, const char *path, int line)
{
    snprintf(where, 4300, "%s:%d", path, line);
    return where;
}

/* Checks text (NUL-terminated, `size` bytes before the NUL) and counts its data lines (not
 * comments, not blank). */
static int scan(const char *path, char *text, size_t size, size_t *n_data, sp_error *err)
{
    if (memchr(text, 0, size))
        return sp_error_set(err, SP_E_FORMAT, "%s: contains NUL bytes (a binary file named .txt?)", path);
    *n_data = 0;
    for (char *p = text; *p;) {
        char *e = strchr(p, '\n');
        if (e) *e = 0;
        *n_data += is_data(p);
        if (!e) break;
        *e = '\n';
        p = e + 1;
    }
    return SP_OK;
}

/* ---- readers ---------------------------------------------------------------------------------- */

static int read_cameras(const char *path, char *buf, size_t size, sp_colmap_model *m, tokens *t, sp_error *err)
{
    char where[4300];
    size_t n;
    int rc = scan(path, buf, size, &n, err);
    if (rc) return rc;
    m->cameras = calloc(n ? n : 1, sizeof *m->cameras);
    if (!m->cameras) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    lines L = {buf, 0};
    for (char *s; !rc && (s = next_line(&L));) {
        if (!is_data(s)) continue;
        if (split(s, t)) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            break;
        }
        sp_colmap_camera *c = &m->cameras[m->n_cameras];
        if (t->n < 4) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS..., got %zu fields",
                              path, L.line, t->n);
            break;
        }
        if ((rc = parse_u32(path, L.line, "CAMERA_ID", t->tok[0], &c->id, err))) break;
        c->model = sp_colmap_model_from_name(t->tok[1]);
        if (c->model < 0) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: unknown camera model '%s'", path, L.line, t->tok[1]);
            break;
        }
        if ((rc = parse_u64(path, L.line, "WIDTH", t->tok[2], UINT64_MAX, &c->width, err)) ||
            (rc = parse_u64(path, L.line, "HEIGHT", t->tok[3], UINT64_MAX, &c->height, err)))
            break;
        c->n_params = sp_colmap_model_num_params(c->model);
        if (t->n - 4 != (size_t)c->n_params) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: camera %u model %s needs %d params, found %zu", path, L.line,
                              c->id, t->tok[1], c->n_params, t->n - 4);
            break;
        }
        for (int k = 0; !rc && k < c->n_params; k++) rc = parse_f64(path, L.line, "PARAMS", t->tok[4 + k], &c->params[k], err);
        if (!rc) rc = colmap_check_camera(at(where, path, L.line), m->n_cameras, c, err);
        m->n_cameras++;
    }
    return rc;
}

static int read_points2d(const char *path, int line, char *s, sp_colmap_image *im, tokens *t, sp_error *err)
{
    if (split(s, t)) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    if (t->n % 3)
        return sp_error_set(err, SP_E_FORMAT, "%s:%d: POINTS2D line of image %u has %zu fields (not a multiple of 3: X Y POINT3D_ID)",
                            path, line, im->id, t->n);
    size_t np = t->n / 3;
    im->n_points2d = 0;
    if (!np) return SP_OK;
    im->xys = malloc(np * 2 * sizeof(double));
    im->point3d_ids = malloc(np * sizeof(int64_t));
    if (!im->xys || !im->point3d_ids) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    im->n_points2d = np;
    for (size_t k = 0; k < np; k++) {
        int rc;
        if ((rc = parse_f64(path, line, "X", t->tok[3 * k], &im->xys[2 * k], err)) ||
            (rc = parse_f64(path, line, "Y", t->tok[3 * k + 1], &im->xys[2 * k + 1], err)))
            return rc;
        char *end;
        errno = 0;
        long long id = strtoll(t->tok[3 * k + 2], &end, 10);
        if (*end || end == t->tok[3 * k + 2] || errno || id < -1)
            return bad_field(path, line, "POINT3D_ID", t->tok[3 * k + 2], err);
        im->point3d_ids[k] = id;
    }
    return SP_OK;
}

static int read_images(const char *path, char *buf, size_t size, sp_colmap_model *m, tokens *t, sp_error *err)
{
    char where[4300];
    size_t n;
    int rc = scan(path, buf, size, &n, err);
    if (rc) return rc;
    /* At most one image per data line (the POINTS2D lines are data lines too). */
    m->images = calloc(n ? n : 1, sizeof *m->images);
    if (!m->images) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    lines L = {buf, 0};
    for (char *s; !rc && (s = next_line(&L));) {
        if (!is_data(s)) continue;
        sp_colmap_image *im = &m->images[m->n_images++];
        /* The name is everything after CAMERA_ID, so names with spaces survive. */
        char *p = s;
        int nf = 0;
        for (; nf < 9; nf++) {
            while (isspace((unsigned char)*p)) p++;
            if (!*p) break;
            while (*p && !isspace((unsigned char)*p)) p++;
        }
        while (isspace((unsigned char)*p)) p++;
        char *name = p;
        size_t nl = strlen(name);
        while (nl && isspace((unsigned char)name[nl - 1])) nl--;
        if (nf < 9 || nl == 0) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s:%d: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME", path, L.line);
            break;
        }
        im->name = malloc(nl + 1);
        if (!im->name) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            break;
        }
        memcpy(im->name, name, nl);
        im->name[nl] = 0;
        *name = 0;
        if (split(s, t)) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            break;
        }
        static const char *fields[] = {"QW", "QX", "QY", "QZ", "TX", "TY", "TZ"};
        if ((rc = parse_u32(path, L.line, "IMAGE_ID", t->tok[0], &im->id, err))) break;
        for (int k = 0; !rc && k < 7; k++)
            rc = parse_f64(path, L.line, fields[k], t->tok[1 + k], k < 4 ? &im->qvec[k] : &im->tvec[k - 4], err);
        if (rc || (rc = parse_u32(path, L.line, "CAMERA_ID", t->tok[8], &im->camera_id, err))) break;
        if ((rc = colmap_check_image(at(where, path, L.line), m->n_images - 1, im, err))) break;
        /* The POINTS2D line follows directly, even when empty; a file may end without it. */
        char *pts = next_line(&L);
        if (pts && (rc = read_points2d(path, L.line, pts, im, t, err))) break;
        rc = colmap_check_image(at(where, path, L.line), m->n_images - 1, im, err);
    }
    return rc;
}

static int read_points(const char *path, char *buf, size_t size, sp_colmap_model *m, tokens *t, sp_error *err)
{
    char where[4300];
    size_t n;
    int rc = scan(path, buf, size, &n, err);
    if (rc) return rc;
    m->points = calloc(n ? n : 1, sizeof *m->points);
    if (!m->points) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    lines L = {buf, 0};
    for (char *s; !rc && (s = next_line(&L));) {
        if (!is_data(s)) continue;
        if (split(s, t)) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
            break;
        }
        sp_colmap_point *p = &m->points[m->n_points++];
        if (t->n < 8 || (t->n - 8) % 2) {
            rc = sp_error_set(err, SP_E_FORMAT,
                              "%s:%d: expected POINT3D_ID X Y Z R G B ERROR then (IMAGE_ID POINT2D_IDX) pairs, got %zu fields",
                              path, L.line, t->n);
            break;
        }
        static const char *fields[] = {"X", "Y", "Z", "R", "G", "B"};
        if ((rc = parse_u64(path, L.line, "POINT3D_ID", t->tok[0], UINT64_MAX, &p->id, err))) break;
        for (int k = 0; !rc && k < 3; k++) rc = parse_f64(path, L.line, fields[k], t->tok[1 + k], &p->xyz[k], err);
        for (int k = 0; !rc && k < 3; k++) {
            uint64_t v;
            rc = parse_u64(path, L.line, fields[3 + k], t->tok[4 + k], 255, &v, err);
            p->rgb[k] = (uint8_t)v;
        }
        if (rc || (rc = parse_f64(path, L.line, "ERROR", t->tok[7], &p->error, err))) break;
        size_t tl = (t->n - 8) / 2;
        if (tl) {
            p->track = malloc(tl * 2 * sizeof(uint32_t));
            if (!p->track) {
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
                break;
            }
        }
        p->track_len = tl;
        for (size_t k = 0; !rc && k < 2 * tl; k++)
            rc = parse_u32(path, L.line, k % 2 ? "POINT2D_IDX" : "IMAGE_ID", t->tok[8 + k], &p->track[k], err);
        if (!rc) rc = colmap_check_point(at(where, path, L.line), m->n_points - 1, p, err);
    }
    return rc;
}

typedef int (*txt_reader)(const char *path, char *buf, size_t size, sp_colmap_model *m, tokens *t, sp_error *err);
static const txt_reader readers[3] = {read_cameras, read_images, read_points};

int sp_colmap_parse_txt(sp_colmap_part part, const char *text, size_t size, const char *name, sp_colmap_model *m,
                        sp_error *err)
{
    int rc = colmap_check_part(part, name, m, err);
    if (rc) return rc;
    char *buf = malloc(size + 1);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu bytes", name, size);
    if (size) memcpy(buf, text, size);
    buf[size] = 0;
    tokens t = {0};
    rc = readers[part](name, buf, size, m, &t, err);
    free(t.tok);
    free(buf);
    return rc;
}

static int parse_txt(sp_colmap_part part, const void *data, size_t size, const char *name, sp_colmap_model *m,
                     sp_error *err)
{
    return sp_colmap_parse_txt(part, data, size, name, m, err);
}

int sp_colmap_read_txt(const char *dir, sp_colmap_model *m, sp_error *err)
{
    return colmap_read_dir(dir, "txt", parse_txt, m, err);
}

/* ---- writers ---------------------------------------------------------------------------------- */

static int open_out(const char *dir, const char *name, char *path, char *tmp, FILE **f, sp_error *err)
{
    if (sp_path_join(path, 4200, dir, name)) return sp_error_set(err, SP_E_ARG, "%s: path too long", dir);
    *f = io_tmp_open(path, tmp, 4300, err);
    return *f ? SP_OK : (err ? err->code : SP_E_IO);
}

int sp_colmap_write_txt(const char *dir, const sp_colmap_model *m, sp_error *err)
{
    char path[4200], tmp[4300];
    FILE *f;
    int rc = sp_mkdirs(dir, err);
    if (rc || (rc = open_out(dir, "cameras.txt", path, tmp, &f, err))) return rc;
    fprintf(f, "# Camera list with one line of data per camera:\n#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
               "# Number of cameras: %zu\n", m->n_cameras);
    for (size_t i = 0; i < m->n_cameras; i++) {
        const sp_colmap_camera *c = &m->cameras[i];
        const char *name = sp_colmap_model_name(c->model);
        if (!name || sp_colmap_model_num_params(c->model) != c->n_params) {
            rc = sp_error_set(err, SP_E_ARG, "%s: camera %u has model %d with %d params", path, c->id, c->model, c->n_params);
            io_tmp_commit(f, tmp, path, 0, NULL);
            return rc;
        }
        fprintf(f, "%u %s %llu %llu", c->id, name, (unsigned long long)c->width, (unsigned long long)c->height);
        for (int k = 0; k < c->n_params; k++) fprintf(f, " %.17g", c->params[k]);
        fputc('\n', f);
    }
    if ((rc = io_tmp_commit(f, tmp, path, 1, err)) || (rc = open_out(dir, "images.txt", path, tmp, &f, err))) return rc;
    size_t obs = 0;
    for (size_t i = 0; i < m->n_images; i++) obs += m->images[i].n_points2d;
    fprintf(f, "# Image list with two lines of data per image:\n"
               "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
               "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
               "# Number of images: %zu, mean observations per image: %.17g\n",
            m->n_images, m->n_images ? (double)obs / (double)m->n_images : 0.0);
    for (size_t i = 0; i < m->n_images; i++) {
        const sp_colmap_image *im = &m->images[i];
        fprintf(f, "%u", im->id);
        for (int k = 0; k < 4; k++) fprintf(f, " %.17g", im->qvec[k]);
        for (int k = 0; k < 3; k++) fprintf(f, " %.17g", im->tvec[k]);
        fprintf(f, " %u %s\n", im->camera_id, im->name ? im->name : "");
        for (size_t k = 0; k < im->n_points2d; k++)
            fprintf(f, "%s%.17g %.17g %lld", k ? " " : "", im->xys[2 * k], im->xys[2 * k + 1],
                    (long long)im->point3d_ids[k]);
        fputc('\n', f);
    }
    if ((rc = io_tmp_commit(f, tmp, path, 1, err)) || (rc = open_out(dir, "points3D.txt", path, tmp, &f, err))) return rc;
    size_t tracks = 0;
    for (size_t i = 0; i < m->n_points; i++) tracks += m->points[i].track_len;
    fprintf(f, "# 3D point list with one line of data per point:\n"
               "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
               "# Number of points: %zu, mean track length: %.17g\n",
            m->n_points, m->n_points ? (double)tracks / (double)m->n_points : 0.0);
    for (size_t i = 0; i < m->n_points; i++) {
        const sp_colmap_point *p = &m->points[i];
        fprintf(f, "%llu %.17g %.17g %.17g %u %u %u %.17g", (unsigned long long)p->id, p->xyz[0], p->xyz[1], p->xyz[2],
                p->rgb[0], p->rgb[1], p->rgb[2], p->error);
        for (size_t k = 0; k < p->track_len; k++) fprintf(f, " %u %u", p->track[2 * k], p->track[2 * k + 1]);
        fputc('\n', f);
    }
    return io_tmp_commit(f, tmp, path, 1, err);
}
