/* Maps in Nav2 map_server's format: a trinary PGM (free 254, occupied 0, unknown 205, image row
 * 0 at the top = the largest y) beside a YAML (image, mode, resolution, origin of the lower-left
 * pixel, negate, occupied_thresh, free_thresh), written atomically; and the loader with
 * map_server's rules (nav2_map_server/src/map_io.cpp: channels averaged to a shade, occ = 1 -
 * shade or shade when negated, strict thresholds, trinary/scale/raw modes). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav_internal.h"
#include "semsplat/io.h"

#define PGM_FREE 254
#define PGM_OCCUPIED 0
#define PGM_UNKNOWN 205
#define MAP_OCCUPIED_THRESH 0.65
/* 205 reads back as occ = 1 - 205/255 = 0.19608; map_saver's default free_thresh 0.25 turns it
 * into free space. Below 0.196 it stays unknown. */
#define MAP_FREE_THRESH 0.19

/* "dir/map.yaml" -> "dir/map.pgm" (image_path) and "map.pgm" (image_name). */
static void pgm_names(const char *yaml_path, char *image_path, size_t cap, const char **image_name)
{
    snprintf(image_path, cap, "%s", yaml_path);
    char *dot = strrchr(image_path, '.'), *slash = strrchr(image_path, '/');
    if (dot && (!slash || dot > slash)) *dot = 0;
    size_t l = strlen(image_path);
    snprintf(image_path + l, cap - l, ".pgm");
    slash = strrchr(image_path, '/');
    *image_name = slash ? slash + 1 : image_path;
}

int sp_costmap_write_map(const sp_costmap *cm, const char *yaml_path, sp_error *err)
{
    char image_path[4096];
    const char *image_name;
    pgm_names(yaml_path, image_path, sizeof image_path, &image_name);
    char header[256];
    int hl = snprintf(header, sizeof header, "P5\n# semsplat costmap, %.4f m/cell\n%d %d\n255\n",
                      cm->res, cm->nx, cm->ny);
    size_t n = (size_t)cm->nx * cm->ny;
    uint8_t *buf = malloc((size_t)hl + n);
    if (!buf) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", image_path);
    memcpy(buf, header, (size_t)hl);
    for (int y = 0; y < cm->ny; y++) {
        const uint8_t *row = cm->occ + (size_t)(cm->ny - 1 - y) * cm->nx;
        uint8_t *out = buf + hl + (size_t)y * cm->nx;
        for (int x = 0; x < cm->nx; x++)
            out[x] = row[x] == SP_CELL_FREE ? PGM_FREE : row[x] == SP_CELL_OCCUPIED ? PGM_OCCUPIED
                                                                                  : PGM_UNKNOWN;
    }
    int rc = sp_write_file_atomic(image_path, buf, (size_t)hl + n, err);
    free(buf);
    if (rc) return rc;
    char yaml[1024];
    int yl = snprintf(yaml, sizeof yaml,
                      "image: %s\nmode: trinary\nresolution: %.6g\norigin: [%.6f, %.6f, 0.0]\n"
                      "negate: 0\noccupied_thresh: %.2f\nfree_thresh: %.2f\n"
                      "# written by semsplat: free 254, occupied 0, unknown 205 (free_thresh below\n"
                      "# 0.196 so that unknown is not read back as free)\n",
                      image_name, cm->res, cm->origin[0], cm->origin[1], MAP_OCCUPIED_THRESH,
                      MAP_FREE_THRESH);
    return sp_write_file_atomic(yaml_path, yaml, (size_t)yl, err);
}

/* ---- reading ---------------------------------------------------------------------------------- */

typedef struct map_yaml {
    char image[1024];
    double resolution, origin[3], free_thresh, occupied_thresh;
    int negate, mode; /* 0 trinary, 1 scale, 2 raw */
    unsigned have;    /* bit per required key */
} map_yaml;

enum { K_IMAGE = 1, K_RES = 2, K_ORIGIN = 4, K_FREE = 8, K_OCC = 16, K_NEGATE = 32 };

static char *trim(char *s)
{
    while (isspace((unsigned char)*s)) s++;
    char *e = s + strlen(s);
    while (e > s && isspace((unsigned char)e[-1])) *--e = 0;
    if ((s[0] == '"' || s[0] == '\'') && e - s >= 2 && e[-1] == s[0]) {
        e[-1] = 0;
        s++;
    }
    return s;
}

static int parse_number(const char *path, int line, const char *key, const char *v, double *out,
                        sp_error *err)
{
    char *end;
    errno = 0;
    double d = strtod(v, &end);
    if (end == v || *trim(end) || errno || !isfinite(d))
        return sp_error_set(err, SP_E_FORMAT, "%s:%d: '%s' is not a number: '%s'", path, line, key, v);
    *out = d;
    return SP_OK;
}

/* origin: "[x, y, yaw]" (flow) or the block form on the next lines ("- x"). */
static int parse_origin(const char *path, int line, char *v, char **rest, map_yaml *m, sp_error *err)
{
    int n = 0;
    if (*v == '[') {
        char *close = strchr(v, ']');
        if (!close) return sp_error_set(err, SP_E_FORMAT, "%s:%d: 'origin' has no closing ']'", path, line);
        *close = 0;
        for (char *tok = strtok(v + 1, ","); tok; tok = strtok(NULL, ",")) {
            if (n == 3) return sp_error_set(err, SP_E_FORMAT, "%s:%d: 'origin' should have 3 elements, not more", path, line);
            int rc = parse_number(path, line, "origin", trim(tok), &m->origin[n++], err);
            if (rc) return rc;
        }
    } else if (!*v) {
        while (*rest && n < 4) {
            char *nl = strchr(*rest, '\n'), *l = *rest;
            if (nl) *nl = 0;
            char *t = trim(l);
            if (t[0] != '-') {
                if (nl) *nl = '\n';
                break;
            }
            if (n == 3) return sp_error_set(err, SP_E_FORMAT, "%s:%d: 'origin' should have 3 elements, not more", path, line);
            int rc = parse_number(path, line, "origin", trim(t + 1), &m->origin[n++], err);
            if (rc) return rc;
            *rest = nl ? nl + 1 : NULL;
        }
    }
    if (n != 3)
        return sp_error_set(err, SP_E_FORMAT, "%s:%d: 'origin' should have 3 elements [x, y, yaw], not %d",
                            path, line, n);
    return SP_OK;
}

static int parse_yaml(const char *path, char *text, map_yaml *m, sp_error *err)
{
    memset(m, 0, sizeof *m);
    int line = 0, rc = 0;
    char *rest = text;
    while (rest && !rc) {
        char *l = rest, *nl = strchr(rest, '\n');
        if (nl) *nl = 0;
        rest = nl ? nl + 1 : NULL;
        line++;
        char *hash = strchr(l, '#');
        if (hash) *hash = 0;
        char *colon = strchr(l, ':');
        if (!*trim(l)) continue;
        if (!colon) return sp_error_set(err, SP_E_FORMAT, "%s:%d: expected 'key: value'", path, line);
        *colon = 0;
        char *key = trim(l), *v = trim(colon + 1);
        if (!strcmp(key, "image")) {
            if (!*v) return sp_error_set(err, SP_E_FORMAT, "%s:%d: the image tag is empty", path, line);
            snprintf(m->image, sizeof m->image, "%s", v);
            m->have |= K_IMAGE;
        } else if (!strcmp(key, "resolution")) {
            rc = parse_number(path, line, key, v, &m->resolution, err);
            m->have |= K_RES;
        } else if (!strcmp(key, "origin")) {
            rc = parse_origin(path, line, v, &rest, m, err);
            m->have |= K_ORIGIN;
        } else if (!strcmp(key, "free_thresh")) {
            rc = parse_number(path, line, key, v, &m->free_thresh, err);
            m->have |= K_FREE;
        } else if (!strcmp(key, "occupied_thresh")) {
            rc = parse_number(path, line, key, v, &m->occupied_thresh, err);
            m->have |= K_OCC;
        } else if (!strcmp(key, "negate")) {
            double d = 0;
            if (!strcmp(v, "true") || !strcmp(v, "True")) d = 1;
            else if (strcmp(v, "false") && strcmp(v, "False")) rc = parse_number(path, line, key, v, &d, err);
            m->negate = d != 0;
            m->have |= K_NEGATE;
        } else if (!strcmp(key, "mode")) {
            if (!strcmp(v, "trinary")) m->mode = 0;
            else if (!strcmp(v, "scale")) m->mode = 1;
            else if (!strcmp(v, "raw")) m->mode = 2;
            else return sp_error_set(err, SP_E_FORMAT, "%s:%d: mode '%s' is not trinary, scale or raw", path, line, v);
        }
    }
    if (rc) return rc;
    static const char *names[] = {"image", "resolution", "origin", "free_thresh", "occupied_thresh", "negate"};
    for (int k = 0; k < 6; k++)
        if (!(m->have & (1u << k)))
            return sp_error_set(err, SP_E_FORMAT, "%s: the required key '%s' is missing", path, names[k]);
    if (!(m->resolution > 0))
        return sp_error_set(err, SP_E_FORMAT, "%s: resolution %g is not positive", path, m->resolution);
    /* The grid is kept in single precision: a cell size or an origin that a float cannot hold
     * (or that is no indoor map: the origin 1000 km away) is refused, not rounded to 0 or inf. */
    if (m->resolution < 1e-6 || m->resolution > 1e3)
        return sp_error_set(err, SP_E_FORMAT, "%s: resolution %g m per cell is outside 1e-6..1e3", path, m->resolution);
    if (fabs(m->origin[0]) > 1e6 || fabs(m->origin[1]) > 1e6)
        return sp_error_set(err, SP_E_FORMAT, "%s: origin [%g, %g] is more than 1000 km from the frame's origin",
                            path, m->origin[0], m->origin[1]);
    /* map_server's meaning needs 0 <= free_thresh < occupied_thresh <= 1 (scale mode divides by
     * their difference: equal thresholds made every cell between them NaN). */
    if (!(m->free_thresh >= 0 && m->free_thresh < m->occupied_thresh && m->occupied_thresh <= 1))
        return sp_error_set(err, SP_E_FORMAT, "%s: thresholds free %g, occupied %g: need 0 <= free_thresh < "
                            "occupied_thresh <= 1", path, m->free_thresh, m->occupied_thresh);
    if (fabs(m->origin[2]) > 1e-6)
        return sp_error_set(err, SP_E_UNSUPPORTED, "%s: origin yaw %g: rotated maps are not supported "
                            "(the grid is axis-aligned in the world frame)", path, m->origin[2]);
    return SP_OK;
}

/* PGM (P5 8/16-bit or P2) into an sp_image (1 channel). */
static int read_pgm(const char *path, const char *data, size_t size, sp_image *img, sp_error *err)
{
    int ascii = data[1] == '2';
    size_t p = 2;
    long v[3];
    for (int k = 0; k < 3; k++) {
        for (;;) {
            while (p < size && isspace((unsigned char)data[p])) p++;
            if (p < size && data[p] == '#') {
                while (p < size && data[p] != '\n') p++;
                continue;
            }
            break;
        }
        char *end;
        v[k] = p < size ? strtol(data + p, &end, 10) : -1;
        if (p >= size || end == data + p || v[k] <= 0)
            return sp_error_set(err, SP_E_FORMAT, "%s: bad PGM header (width, height, maxval)", path);
        p = (size_t)(end - data);
    }
    if (v[0] > 65536 || v[1] > 65536 || v[2] > 65535)
        return sp_error_set(err, SP_E_FORMAT, "%s: PGM %ldx%ld maxval %ld out of range", path, v[0], v[1], v[2]);
    int bytes = v[2] > 255 ? 2 : 1;
    size_t n = (size_t)v[0] * v[1];
    /* The file must hold every pixel before anything is allocated: a 20-byte header claiming
     * 53235 x 53235 is refused as truncated, not answered with a 2.8 GB allocation. Binary:
     * one whitespace byte, then n * bytes; ASCII: each value after at least one separator. */
    size_t need = ascii ? 2 * n : 1 + n * bytes, have = size - p;
    if (have < need)
        return sp_error_set(err, SP_E_FORMAT, "%s: PGM truncated: %zu bytes after the header for %ldx%ld pixels",
                            path, have, v[0], v[1]);
    memset(img, 0, sizeof *img);
    img->width = (int)v[0], img->height = (int)v[1], img->channels = 1;
    img->bit_depth = bytes == 2 ? 16 : 8;
    img->data = malloc(n * bytes);
    if (!img->data) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    uint8_t *d8 = img->data;
    uint16_t *d16 = img->data;
    long maxv = v[2];
    if (ascii) {
        for (size_t i = 0; i < n; i++) {
            char *end;
            while (p < size && isspace((unsigned char)data[p])) p++;
            long x = p < size ? strtol(data + p, &end, 10) : -1;
            if (p >= size || end == data + p || x < 0 || x > maxv) {
                sp_image_free(img);
                return sp_error_set(err, SP_E_FORMAT, "%s: PGM pixel %zu missing or out of range", path, i);
            }
            p = (size_t)(end - data);
            if (bytes == 2) d16[i] = (uint16_t)(x * 65535 / maxv);
            else d8[i] = (uint8_t)(x * 255 / maxv);
        }
        return SP_OK;
    }
    p++; /* one whitespace byte after maxval */
    if (size < p + n * bytes) {
        sp_image_free(img);
        return sp_error_set(err, SP_E_FORMAT, "%s: PGM truncated: %zu pixel bytes for %ldx%ld", path,
                            size > p ? size - p : 0, v[0], v[1]);
    }
    for (size_t i = 0; i < n; i++) {
        long x = bytes == 2 ? ((long)(uint8_t)data[p + 2 * i] << 8) | (uint8_t)data[p + 2 * i + 1]
                            : (uint8_t)data[p + i];
        if (bytes == 2) d16[i] = (uint16_t)(x * 65535 / maxv);
        else d8[i] = (uint8_t)(x * 255 / maxv);
    }
    return SP_OK;
}

static int read_map_image(const char *path, sp_image *img, sp_error *err)
{
    char *data = NULL;
    size_t size = 0;
    int rc = sp_read_file(path, &data, &size, err);
    if (rc) return rc;
    if (size >= 2 && data[0] == 'P' && (data[1] == '5' || data[1] == '2')) rc = read_pgm(path, data, size, img, err);
    else rc = sp_image_read(path, img, err);
    free(data);
    return rc;
}

/* map_server's cell value (0..100, -1) of pixel (x, y). */
static int map_value(const sp_image *img, int x, int y, const map_yaml *m)
{
    int c = img->channels, has_alpha = c == 2 || c == 4, colours = has_alpha ? c - 1 : c;
    double maxv = img->bit_depth == 16 ? 65535.0 : 255.0, sum = 0, alpha = maxv;
    size_t base = ((size_t)y * img->width + x) * c;
    for (int k = 0; k < c; k++) {
        double v = img->bit_depth == 16 ? ((uint16_t *)img->data)[base + k] : ((uint8_t *)img->data)[base + k];
        if (k < colours) sum += v;
        else alpha = v;
    }
    int nch = colours;
    if (m->mode == 0 && has_alpha) sum += alpha, nch++; /* trinary averages opacity in */
    double shade = sum / nch / maxv, occ = m->negate ? shade : 1.0 - shade;
    if (m->mode == 2) {
        double pct = round(shade * 255);
        return pct >= 0 && pct <= 100 ? (int)pct : -1;
    }
    if (m->mode == 1 && has_alpha && alpha != maxv) return -1;
    if (m->occupied_thresh < occ) return 100;
    if (occ < m->free_thresh) return 0;
    if (m->mode == 0) return -1;
    return (int)rint((occ - m->free_thresh) / (m->occupied_thresh - m->free_thresh) * 100.0);
}

int sp_costmap_read_map(sp_costmap *cm, const char *yaml_path, const sp_costmap_opts *opts,
                        sp_error *err)
{
    memset(cm, 0, sizeof *cm);
    char *text = NULL;
    size_t size;
    int rc = sp_read_file(yaml_path, &text, &size, err);
    if (rc) return rc;
    map_yaml m;
    rc = parse_yaml(yaml_path, text, &m, err);
    free(text);
    if (rc) return rc;
    char image_path[4096];
    if (m.image[0] == '/') {
        snprintf(image_path, sizeof image_path, "%s", m.image);
    } else {
        snprintf(image_path, sizeof image_path, "%s", yaml_path);
        char *slash = strrchr(image_path, '/');
        if (slash) slash[1] = 0;
        else image_path[0] = 0;
        size_t l = strlen(image_path);
        snprintf(image_path + l, sizeof image_path - l, "%s", m.image);
    }
    sp_image img;
    if ((rc = read_map_image(image_path, &img, err))) return sp_error_prefix(err, "%s: image: ", yaml_path);
    sp_costmap_opts o = opts ? *opts : sp_costmap_opts_default();
    size_t n = (size_t)img.width * img.height;
    cm->nx = img.width, cm->ny = img.height;
    cm->res = (float)m.resolution;
    cm->origin[0] = (float)m.origin[0], cm->origin[1] = (float)m.origin[1];
    cm->floor_z = 0;
    cm->band[0] = o.band_lo_m, cm->band[1] = o.band_hi_m;
    cm->opts = o;
    cm->opts.resolution_m = cm->res;
    cm->occ = malloc(n);
    cm->cost = malloc(n);
    cm->dist = malloc(n * sizeof(float));
    if (!cm->occ || !cm->cost || !cm->dist) {
        sp_image_free(&img);
        sp_costmap_free(cm);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu cells", yaml_path, n);
    }
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) {
            int v = map_value(&img, x, y, &m);
            /* as Nav2's static layer with trinary_costmap: lethal at 100, unknown at -1, the rest free */
            cm->occ[(size_t)(img.height - y - 1) * img.width + x] =
                v < 0 ? SP_CELL_UNKNOWN : v >= 100 ? SP_CELL_OCCUPIED : SP_CELL_FREE;
        }
    sp_image_free(&img);
    if ((rc = sp_costmap_inflate(cm, &cm->opts, err))) sp_costmap_free(cm);
    return rc;
}
