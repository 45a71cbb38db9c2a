/* Loads a Nav2 map_server map (map.yaml + its PGM) into an occupancy grid, with map_server's
 * rules (nav2_map_server map_io.cpp): occ = negate ? shade : 1 - shade for shade = value/maxval;
 * trinary: occ > occupied_thresh -> 100, occ < free_thresh -> 0, else -1 (unknown); scale: the
 * values between scale linearly to 1..99; raw: the value itself when 0..100. Image row 0 is the
 * top of the map, OccupancyGrid row 0 the bottom, so rows are flipped. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ros_internal.h"

typedef struct {
    char image[1024];
    double resolution, origin[3];
    int negate;
    double occupied_thresh, free_thresh;
    char mode[16];
    int have_res, have_origin;
} map_yaml;

static char *trim(char *s)
{
    while (isspace((unsigned char)*s)) s++;
    char *e = s + strlen(s);
    while (e > s && isspace((unsigned char)e[-1])) *--e = 0;
    if (e - s >= 2 && (*s == '"' || *s == '\'') && e[-1] == *s) {
        e[-1] = 0;
        s++;
    }
    return s;
}

static int parse_number(const char *path, const char *key, const char *v, double *out,
                        sp_error *err)
{
    char *end;
    double x = strtod(v, &end);
    if (end == v || *trim(end) || !isfinite(x))
        return sp_error_set(err, SP_E_FORMAT, "%s: %s: '%s' is not a number", path, key, v);
    *out = x;
    return 0;
}

static int parse_line(const char *path, int line, char *s, map_yaml *m, sp_error *err)
{
    char *hash = strchr(s, '#');
    if (hash) *hash = 0;
    char *colon = strchr(s, ':');
    if (!*trim(s)) return 0;
    if (!colon)
        return sp_error_set(err, SP_E_FORMAT, "%s:%d: expected 'key: value'", path, line);
    *colon = 0;
    char *key = trim(s), *v = trim(colon + 1);
    double x;
    if (!strcmp(key, "image")) {
        snprintf(m->image, sizeof m->image, "%s", v);
    } else if (!strcmp(key, "resolution")) {
        if (parse_number(path, key, v, &m->resolution, err)) return SP_E_FORMAT;
        m->have_res = 1;
    } else if (!strcmp(key, "origin")) {
        if (sscanf(v, "[ %lf , %lf , %lf ]", &m->origin[0], &m->origin[1], &m->origin[2]) != 3 ||
            !isfinite(m->origin[0]) || !isfinite(m->origin[1]) || !isfinite(m->origin[2]))
            return sp_error_set(err, SP_E_FORMAT, "%s:%d: origin '%s' is not [x, y, yaw]", path,
                                line, v);
        m->have_origin = 1;
    } else if (!strcmp(key, "negate")) {
        if (parse_number(path, key, v, &x, err)) return SP_E_FORMAT;
        m->negate = x != 0;
    } else if (!strcmp(key, "occupied_thresh")) {
        if (parse_number(path, key, v, &m->occupied_thresh, err)) return SP_E_FORMAT;
    } else if (!strcmp(key, "free_thresh")) {
        if (parse_number(path, key, v, &m->free_thresh, err)) return SP_E_FORMAT;
    } else if (!strcmp(key, "mode")) {
        snprintf(m->mode, sizeof m->mode, "%s", v);
    }
    return 0; /* other keys (e.g. map_server's) are not ours to judge */
}

static int read_yaml(const char *path, map_yaml *m, sp_error *err)
{
    char *text;
    size_t size;
    if (sp_read_file(path, &text, &size, err)) return err ? err->code : SP_E_IO;
    memset(m, 0, sizeof *m);
    m->occupied_thresh = 0.65;
    m->free_thresh = 0.196;
    snprintf(m->mode, sizeof m->mode, "trinary");
    int rc = 0, line = 1;
    for (char *s = text, *nl; s && *s && !rc; s = nl ? nl + 1 : NULL, line++) {
        nl = strchr(s, '\n');
        if (nl) *nl = 0;
        rc = parse_line(path, line, s, m, err);
    }
    free(text);
    if (rc) return rc;
    if (!m->image[0] || !m->have_res || !m->have_origin)
        return sp_error_set(err, SP_E_FORMAT, "%s: needs image, resolution and origin", path);
    if (!(m->resolution > 0))
        return sp_error_set(err, SP_E_FORMAT, "%s: resolution %g is not positive", path,
                            m->resolution);
    if (!(m->free_thresh >= 0 && m->free_thresh < m->occupied_thresh && m->occupied_thresh <= 1))
        return sp_error_set(err, SP_E_FORMAT, "%s: thresholds free %g, occupied %g (need 0 <= "
                            "free < occupied <= 1)", path, m->free_thresh, m->occupied_thresh);
    if (strcmp(m->mode, "trinary") && strcmp(m->mode, "scale") && strcmp(m->mode, "raw"))
        return sp_error_set(err, SP_E_FORMAT, "%s: mode '%s' (trinary, scale or raw)", path,
                            m->mode);
    return 0;
}

/* Next PGM header integer, skipping whitespace and # comments. */
static int pgm_int(const unsigned char *d, size_t n, size_t *pos, long *out)
{
    while (*pos < n) {
        if (d[*pos] == '#')
            while (*pos < n && d[*pos] != '\n') (*pos)++;
        else if (isspace(d[*pos])) (*pos)++;
        else break;
    }
    if (*pos >= n || !isdigit(d[*pos])) return -1;
    long v = 0;
    while (*pos < n && isdigit(d[*pos]) && v < 1000000) v = v * 10 + (d[(*pos)++] - '0');
    *out = v;
    return 0;
}

static int8_t cell_value(const map_yaml *m, double shade)
{
    if (!strcmp(m->mode, "raw")) {
        double v = round(shade * 255);
        return v <= 100 ? (int8_t)v : -1;
    }
    double occ = m->negate ? shade : 1.0 - shade;
    if (occ > m->occupied_thresh) return 100;
    if (occ < m->free_thresh) return 0;
    if (!strcmp(m->mode, "trinary")) return -1;
    return (int8_t)rint((occ - m->free_thresh) / (m->occupied_thresh - m->free_thresh) * 100.0);
}

static int read_pgm(const char *path, const map_yaml *m, sp_ros_grid *g, sp_error *err)
{
    char *data;
    size_t n;
    if (sp_read_file(path, &data, &n, err)) return err ? err->code : SP_E_IO;
    const unsigned char *d = (const unsigned char *)data;
    size_t pos = 2;
    long w, h, maxval;
    int rc = 0;
    int binary = n > 2 && d[0] == 'P' && d[1] == '5', ascii = n > 2 && d[0] == 'P' && d[1] == '2';
    if (!binary && !ascii) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: not a PGM (P5 or P2) image", path);
    } else if (pgm_int(d, n, &pos, &w) || pgm_int(d, n, &pos, &h) ||
               pgm_int(d, n, &pos, &maxval) || w <= 0 || h <= 0 || w > 65536 || h > 65536 ||
               maxval <= 0 || maxval > 255) {
        rc = sp_error_set(err, SP_E_FORMAT, "%s: bad PGM header (8-bit images only)", path);
    } else if (!(g->cells = malloc((size_t)w * h))) {
        rc = sp_error_set(err, SP_E_NOMEM, "%s: %ld x %ld", path, w, h);
    } else {
        if (pos < n) pos++; /* the single whitespace after maxval (none when the file ends there) */
        size_t avail = n > pos ? n - pos : 0;
        if (binary && avail < (size_t)w * h)
            rc = sp_error_set(err, SP_E_FORMAT, "%s: %zu pixel bytes for %ld x %ld", path, avail, w, h);
        for (long i = 0; i < w * h && !rc; i++) {
            long v = binary ? d[pos + i] : -1;
            if (ascii && (pgm_int(d, n, &pos, &v) || v > maxval))
                rc = sp_error_set(err, SP_E_FORMAT, "%s: pixel %ld missing or > maxval", path, i);
            long row = i / w, col = i % w;
            if (!rc) g->cells[(h - 1 - row) * w + col] = cell_value(m, (double)v / maxval);
        }
        g->width = (int)w;
        g->height = (int)h;
    }
    free(data);
    if (rc) sp_ros_grid_free(g);
    return rc;
}

int sp_ros_grid_load_yaml(const char *yaml_path, sp_ros_grid *out, sp_error *err)
{
    map_yaml m;
    if (read_yaml(yaml_path, &m, err)) return err ? err->code : SP_E_FORMAT;
    char image[2048];
    const char *slash = strrchr(yaml_path, '/');
    if (m.image[0] == '/' || !slash)
        snprintf(image, sizeof image, "%s", m.image);
    else
        snprintf(image, sizeof image, "%.*s/%s", (int)(slash - yaml_path), yaml_path, m.image);
    sp_ros_grid g;
    memset(&g, 0, sizeof g);
    int rc = read_pgm(image, &m, &g, err);
    if (rc) return rc;
    g.resolution_m = m.resolution;
    g.origin_x = m.origin[0];
    g.origin_y = m.origin[1];
    g.origin_yaw = m.origin[2];
    snprintf(g.frame_id, sizeof g.frame_id, "map");
    *out = g;
    return 0;
}
