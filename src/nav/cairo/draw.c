/* Pictures for people, drawn with Cairo: the top-down map (costmap, 1 m grid, objects found,
 * start, ranked paths or tour poses in distinct colours, legend, scale bar) and a contact sheet of
 * a trajectory's previews with each view's waypoint, distance along the path and
 * localizability. PNGs go through a memory stream and are written atomically. */
#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nav/nav_scene.h"

/* Distinct path colours (Tableau 10), best first. */
static const double palette[10][3] = {
    {0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173}, {0.839, 0.153, 0.157},
    {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761}, {0.498, 0.498, 0.498},
    {0.737, 0.741, 0.133}, {0.090, 0.745, 0.812},
};

enum { MARGIN_L = 56, MARGIN_T = 44, MARGIN_B = 40, PANEL_W = 380 };

int nav_draw_available(const char **why)
{
    if (why) *why = NULL;
    return 1;
}

typedef struct png_buf {
    unsigned char *data;
    size_t n, cap;
} png_buf;

static cairo_status_t png_write(void *closure, const unsigned char *data, unsigned int length)
{
    png_buf *b = closure;
    if (b->n + length > b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 1 << 16;
        while (cap < b->n + length) cap *= 2;
        unsigned char *d = realloc(b->data, cap);
        if (!d) return CAIRO_STATUS_NO_MEMORY;
        b->data = d, b->cap = cap;
    }
    memcpy(b->data + b->n, data, length);
    b->n += length;
    return CAIRO_STATUS_SUCCESS;
}

static int save_png(cairo_surface_t *surf, const char *path, sp_error *err)
{
    png_buf b = {0};
    cairo_status_t st = cairo_surface_write_to_png_stream(surf, png_write, &b);
    int rc = st == CAIRO_STATUS_SUCCESS ? sp_write_file_atomic(path, b.data, b.n, err)
                                        : sp_error_set(err, SP_E_IO, "%s: cairo: %s", path, cairo_status_to_string(st));
    free(b.data);
    return rc;
}

static void cell_colour(const sp_costmap *cm, long i, uint8_t rgb[3])
{
    uint8_t c = cm->cost[i];
    if (cm->occ[i] == SP_CELL_UNKNOWN) rgb[0] = 196, rgb[1] = 198, rgb[2] = 206;
    else if (cm->occ[i] == SP_CELL_OCCUPIED) rgb[0] = 34, rgb[1] = 34, rgb[2] = 38;
    else if (c >= SP_COST_INSCRIBED) rgb[0] = 246, rgb[1] = 200, rgb[2] = 196;
    else {
        /* inflation: white fading to a pale blue with cost */
        float t = (float)c / SP_COST_MAX_NON_OBSTACLE;
        rgb[0] = (uint8_t)(255 - 70 * t), rgb[1] = (uint8_t)(255 - 40 * t), rgb[2] = 255;
    }
}

typedef struct view {
    const sp_costmap *cm;
    double s; /* pixels per cell */
    double map_h;
} view;

static void to_px(const view *v, double x, double y, double *px, double *py)
{
    *px = MARGIN_L + (x - v->cm->origin[0]) / v->cm->res * v->s;
    *py = MARGIN_T + v->map_h - (y - v->cm->origin[1]) / v->cm->res * v->s;
}

static void text_at(cairo_t *cr, double x, double y, double size, int bold, const char *s)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s);
}

/* Text on a translucent white box so it reads over the map. */
static void label(cairo_t *cr, double x, double y, double size, const char *s)
{
    cairo_text_extents_t e;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, size);
    cairo_text_extents(cr, s, &e);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
    cairo_rectangle(cr, x - 2, y - e.height - 3, e.x_advance + 4, e.height + 6);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, x, y, size, 1, s);
}

static void draw_costmap(cairo_t *cr, const view *v)
{
    const sp_costmap *cm = v->cm;
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, cm->nx, cm->ny);
    unsigned char *px = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    cairo_surface_flush(img);
    for (int y = 0; y < cm->ny; y++)
        for (int x = 0; x < cm->nx; x++) {
            uint8_t c[3];
            cell_colour(cm, (long)(cm->ny - 1 - y) * cm->nx + x, c); /* image rows top-down */
            uint32_t *p = (uint32_t *)(px + (size_t)y * stride) + x;
            *p = ((uint32_t)c[0] << 16) | ((uint32_t)c[1] << 8) | c[2];
        }
    cairo_surface_mark_dirty(img);
    cairo_save(cr);
    cairo_translate(cr, MARGIN_L, MARGIN_T);
    cairo_scale(cr, v->s, v->s);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
}

/* 1 m grid with tick labels, and a 1 m scale bar. */
static void draw_grid(cairo_t *cr, const view *v)
{
    const sp_costmap *cm = v->cm;
    double x0 = cm->origin[0], y0 = cm->origin[1], x1 = x0 + cm->nx * cm->res, y1 = y0 + cm->ny * cm->res;
    cairo_set_line_width(cr, 0.5);
    char buf[32];
    for (double x = ceil(x0); x <= x1; x += 1) {
        double a, b, c, d;
        to_px(v, x, y0, &a, &b);
        to_px(v, x, y1, &c, &d);
        cairo_set_source_rgba(cr, 0.3, 0.3, 0.5, 0.25);
        cairo_move_to(cr, a, b), cairo_line_to(cr, c, d), cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", x);
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.3);
        text_at(cr, a - 6, b + 16, 11, 0, buf);
    }
    for (double y = ceil(y0); y <= y1; y += 1) {
        double a, b, c, d;
        to_px(v, x0, y, &a, &b);
        to_px(v, x1, y, &c, &d);
        cairo_set_source_rgba(cr, 0.3, 0.3, 0.5, 0.25);
        cairo_move_to(cr, a, b), cairo_line_to(cr, c, d), cairo_stroke(cr);
        snprintf(buf, sizeof buf, "%g", y);
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.3);
        text_at(cr, a - 30, b + 4, 11, 0, buf);
    }
    double a, b;
    to_px(v, x0, y0, &a, &b);
    double bar = 1.0 / cm->res * v->s;
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 3);
    cairo_move_to(cr, a + 10, b - 12), cairo_line_to(cr, a + 10 + bar, b - 12), cairo_stroke(cr);
    label(cr, a + 10, b - 18, 11, "1 m");
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.3);
    text_at(cr, MARGIN_L + v->s * cm->nx - 70, MARGIN_T + v->map_h + 32, 11, 0, "x (m) ->");
}

/* Where an object's label goes: the first of four spots beside its box (above, below, right,
 * left) that overlaps no label already placed, else (a target's label, which is always drawn)
 * the spot overlapping them least; another object's label that fits nowhere is left out, as
 * map renderers drop colliding labels (its box stays). placed records the labels drawn so far. */
typedef struct label_box {
    double x0, y0, x1, y1;
} label_box;

static double overlap(const label_box *a, const label_box *b)
{
    double w = fmin(a->x1, b->x1) - fmax(a->x0, b->x0), h = fmin(a->y1, b->y1) - fmax(a->y0, b->y0);
    return w > 0 && h > 0 ? w * h : 0;
}

static int place_label(cairo_t *cr, double a, double b, double c, double d, double size, const char *s,
                       int always, const label_box *placed, int n_placed, label_box *out)
{
    cairo_text_extents_t e;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, size);
    cairo_text_extents(cr, s, &e);
    double w = e.x_advance + 4, h = e.height + 6;
    /* candidate baselines: above the box, below it, right of it, left of it */
    const double spot[4][2] = {{a, b - 3}, {a, d + h}, {c + 4, b + h - 3}, {a - w - 2, b + h - 3}};
    label_box best = {0};
    double best_cost = INFINITY;
    for (int k = 0; k < 4; k++) {
        label_box r = {spot[k][0] - 2, spot[k][1] - e.height - 3, spot[k][0] - 2 + w, spot[k][1] + 3};
        double cost = 0;
        for (int j = 0; j < n_placed; j++) cost += overlap(&r, &placed[j]);
        if (cost < best_cost) best = r, best_cost = cost;
        if (cost == 0) break;
    }
    if (best_cost > 0 && !always) return 0;
    label(cr, best.x0 + 2, best.y1 - 3, size, s);
    *out = best;
    return 1;
}

static void draw_objects(cairo_t *cr, const view *v, const nav_map_layers *L)
{
    for (int i = 0; i < L->n_objects; i++) {
        double a, b, c, d;
        to_px(v, L->boxes[i].min[0], L->boxes[i].max[1], &a, &b);
        to_px(v, L->boxes[i].max[0], L->boxes[i].min[1], &c, &d);
        int tgt = L->object_is_target && L->object_is_target[i];
        if (tgt) cairo_set_source_rgba(cr, 0.85, 0.1, 0.1, 0.9);
        else cairo_set_source_rgba(cr, 0.1, 0.5, 0.25, 0.9);
        cairo_set_line_width(cr, tgt ? 2.5 : 1.5);
        cairo_rectangle(cr, a, b, c - a, d - b);
        cairo_stroke(cr);
    }
    /* labels after every box, the targets' first, so they keep the best spots and no later box
     * or label covers them */
    label_box *placed = malloc(sizeof *placed * (size_t)(L->n_objects > 0 ? L->n_objects : 1));
    int n_placed = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < L->n_objects; i++) {
            int tgt = L->object_is_target && L->object_is_target[i];
            if (tgt != (pass == 0)) continue;
            double a, b, c, d;
            to_px(v, L->boxes[i].min[0], L->boxes[i].max[1], &a, &b);
            to_px(v, L->boxes[i].max[0], L->boxes[i].min[1], &c, &d);
            label_box r;
            if (place_label(cr, a, b, c, d, tgt ? 12 : 10, L->object_labels[i], tgt, placed, n_placed, &r) && placed)
                placed[n_placed++] = r;
        }
    free(placed);
    if (L->area) {
        double a, b, c, d;
        to_px(v, L->area->min[0], L->area->max[1], &a, &b);
        to_px(v, L->area->max[0], L->area->min[1], &c, &d);
        static const double dash[2] = {8, 5};
        cairo_set_dash(cr, dash, 2, 0);
        cairo_set_source_rgba(cr, 0.5, 0.2, 0.7, 0.9);
        cairo_set_line_width(cr, 2);
        cairo_rectangle(cr, a, b, c - a, d - b);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0);
    }
}

static void arrow(cairo_t *cr, double x, double y, double yaw, double len)
{
    double ex = x + len * cos(yaw), ey = y - len * sin(yaw);
    cairo_move_to(cr, x, y), cairo_line_to(cr, ex, ey), cairo_stroke(cr);
    for (int s = -1; s <= 1; s += 2) {
        double a = yaw + M_PI + s * 0.5;
        cairo_move_to(cr, ex, ey), cairo_line_to(cr, ex + 0.4 * len * cos(a), ey - 0.4 * len * sin(a));
        cairo_stroke(cr);
    }
}

static void draw_paths(cairo_t *cr, const view *v, const nav_map_layers *L)
{
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (int i = L->n_paths - 1; i >= 0; i--) { /* best on top */
        const sp_path *p = L->paths[i];
        const double *c = palette[i % 10];
        cairo_set_source_rgba(cr, c[0], c[1], c[2], 0.9);
        cairo_set_line_width(cr, i == 0 ? 4 : 3);
        for (int k = 0; k < p->n; k++) {
            double x, y;
            to_px(v, p->waypoints[4 * k], p->waypoints[4 * k + 1], &x, &y);
            if (k) cairo_line_to(cr, x, y);
            else cairo_move_to(cr, x, y);
        }
        cairo_stroke(cr);
        if (p->n < 1) continue;
        double x, y;
        const float *e = p->waypoints + 4 * (p->n - 1);
        to_px(v, e[0], e[1], &x, &y);
        cairo_arc(cr, x, y, 5, 0, 2 * M_PI);
        cairo_fill(cr);
        cairo_set_line_width(cr, 2);
        arrow(cr, x, y, e[3], 16);
        const float *m = p->waypoints + 4 * (p->n / 2);
        to_px(v, m[0], m[1], &x, &y);
        cairo_arc(cr, x, y, 9, 0, 2 * M_PI);
        cairo_fill(cr);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", i + 1);
        cairo_set_source_rgb(cr, 1, 1, 1);
        text_at(cr, x - 4, y + 4, 12, 1, buf);
    }
    for (int i = 0; i < L->n_poses; i++) {
        const float *q = L->poses + 4 * i;
        double x, y;
        to_px(v, q[0], q[1], &x, &y);
        cairo_set_source_rgb(cr, 0.5, 0.2, 0.7);
        cairo_set_line_width(cr, 2);
        arrow(cr, x, y, q[3], 18);
        cairo_arc(cr, x, y, 8, 0, 2 * M_PI);
        cairo_fill(cr);
        char buf[8];
        snprintf(buf, sizeof buf, "%d", i + 1);
        cairo_set_source_rgb(cr, 1, 1, 1);
        text_at(cr, x - (i + 1 >= 10 ? 7 : 4), y + 4, 11, 1, buf);
    }
    if (L->start) {
        double x, y;
        to_px(v, L->start[0], L->start[1], &x, &y);
        cairo_set_source_rgb(cr, 0.0, 0.6, 0.2);
        cairo_arc(cr, x, y, 8, 0, 2 * M_PI);
        cairo_fill(cr);
        cairo_set_line_width(cr, 3);
        arrow(cr, x, y, L->start[2], 22);
        label(cr, x + 10, y - 10, 12, "start");
    }
}

static void swatch(cairo_t *cr, double x, double y, const double c[3], int line)
{
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    if (line) {
        cairo_set_line_width(cr, 4);
        cairo_move_to(cr, x, y - 4), cairo_line_to(cr, x + 24, y - 4), cairo_stroke(cr);
    } else {
        cairo_rectangle(cr, x, y - 11, 24, 12);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        cairo_set_line_width(cr, 0.5);
        cairo_stroke(cr);
    }
}

static void draw_legend(cairo_t *cr, double x0, const nav_map_layers *L)
{
    double y = MARGIN_T + 10;
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    if (L->n_paths) {
        text_at(cr, x0, y, 14, 1, L->n_poses ? "Tour" : "Trajectories (ranked)");
        y += 22;
        for (int i = 0; i < L->n_paths; i++, y += 20) {
            swatch(cr, x0, y, palette[i % 10], 1);
            cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
            text_at(cr, x0 + 32, y, 11, i == 0, L->path_labels[i]);
        }
        y += 12;
    }
    if (L->n_poses) {
        y += 4;
        static const double purple[3] = {0.5, 0.2, 0.7};
        swatch(cr, x0, y, purple, 0);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text_at(cr, x0 + 32, y, 11, 0, "numbered views, in visiting order");
        y += 30;
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, x0, y, 14, 1, "Map");
    y += 20;
    static const struct { double c[3]; const char *what; } keys[] = {
        {{1, 1, 1}, "free (seen by the cameras)"},
        {{0.73, 0.84, 1.0}, "free, near obstacles (inflation)"},
        {{0.96, 0.78, 0.77}, "within the robot radius: no-go"},
        {{0.13, 0.13, 0.15}, "occupied"},
        {{0.77, 0.78, 0.81}, "unknown (never observed): no-go"},
    };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++, y += 18) {
        swatch(cr, x0, y, keys[k].c, 0);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text_at(cr, x0 + 32, y, 11, 0, keys[k].what);
    }
    y += 8;
    static const double red[3] = {0.85, 0.1, 0.1}, green[3] = {0.1, 0.5, 0.25}, start[3] = {0, 0.6, 0.2};
    swatch(cr, x0, y, red, 1);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, x0 + 32, y, 11, 0, "target's footprint");
    y += 18;
    swatch(cr, x0, y, green, 1);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, x0 + 32, y, 11, 0, "other objects found");
    y += 18;
    swatch(cr, x0, y, start, 1);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, x0 + 32, y, 11, 0, "start and heading; arrows: final heading");
}

int nav_draw_map(const nav_map_layers *L, const char *png_path, sp_error *err)
{
    const sp_costmap *cm = L->cm;
    int side = cm->nx > cm->ny ? cm->nx : cm->ny;
    double s = floor(900.0 / side);
    s = s < 2 ? 2 : s > 8 ? 8 : s;
    view v = {cm, s, cm->ny * s};
    int W = (int)(MARGIN_L + cm->nx * s + 20 + PANEL_W), H = (int)(MARGIN_T + v.map_h + MARGIN_B);
    if (H < 520) H = 520;
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H);
    cairo_t *cr = cairo_create(surf);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    draw_costmap(cr, &v);
    draw_grid(cr, &v);
    draw_objects(cr, &v, L);
    draw_paths(cr, &v, L);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text_at(cr, MARGIN_L, 26, 15, 1, L->title ? L->title : "semsplat map");
    draw_legend(cr, MARGIN_L + cm->nx * s + 20, L);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    int rc = st == CAIRO_STATUS_SUCCESS ? save_png(surf, png_path, err)
                                        : sp_error_set(err, SP_E_IO, "%s: cairo: %s", png_path, cairo_status_to_string(st));
    cairo_surface_destroy(surf);
    return rc;
}

/* Fits a line of text into width by shrinking the font, down to 8 px. */
static void fitted_text(cairo_t *cr, double x, double y, double size, int bold, double width, const char *s)
{
    cairo_text_extents_t e;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    for (; size > 8; size -= 0.5) {
        cairo_set_font_size(cr, size);
        cairo_text_extents(cr, s, &e);
        if (e.x_advance <= width) break;
    }
    text_at(cr, x, y, size, bold, s);
}

int nav_draw_sheet(const char *title, const sp_nav_preview *pv, int n, const char *png_path,
                   sp_error *err)
{
    if (n < 1) return sp_error_set(err, SP_E_ARG, "%s: no previews", png_path);
    int cols = n < 4 ? n : 4, rows = (n + cols - 1) / cols, tw = pv[0].width, th = pv[0].height;
    const int gap = 10, cap_h = 52, head = 44;
    int W = cols * (tw + gap) + gap, H = head + rows * (th + cap_h + gap);
    if (W < 640) W = 640;
    cairo_surface_t *surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, W, H);
    cairo_t *cr = cairo_create(surf);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.97);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    fitted_text(cr, gap, 28, 14, 1, W - 2 * gap, title);
    for (int j = 0; j < n; j++) {
        if (!pv[j].rgb || pv[j].width != tw || pv[j].height != th) continue;
        int x = gap + (j % cols) * (tw + gap), y = head + (j / cols) * (th + cap_h + gap);
        cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, tw, th);
        unsigned char *px = cairo_image_surface_get_data(img);
        int stride = cairo_image_surface_get_stride(img);
        cairo_surface_flush(img);
        for (int r = 0; r < th; r++)
            for (int c = 0; c < tw; c++) {
                const uint8_t *q = pv[j].rgb + ((size_t)r * tw + c) * 3;
                ((uint32_t *)(px + (size_t)r * stride))[c] = ((uint32_t)q[0] << 16) | ((uint32_t)q[1] << 8) | q[2];
            }
        cairo_surface_mark_dirty(img);
        cairo_set_source_surface(cr, img, x, y);
        cairo_paint(cr);
        cairo_surface_destroy(img);
        char line[128];
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        snprintf(line, sizeof line, "%d. waypoint %d%s", j + 1, pv[j].waypoint, j == n - 1 ? " (goal)" : "");
        fitted_text(cr, x, y + th + 16, 12, 1, tw, line);
        snprintf(line, sizeof line, "%.1f m along the path", pv[j].distance_m);
        fitted_text(cr, x, y + th + 31, 11, 0, tw, line);
        snprintf(line, sizeof line, "localizability %.2f%s", pv[j].localizability,
                 pv[j].localizability < 0.3f ? " (poor)" : "");
        if (pv[j].localizability < 0.3f) cairo_set_source_rgb(cr, 0.75, 0.1, 0.1);
        fitted_text(cr, x, y + th + 46, 11, 0, tw, line);
    }
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    int rc = st == CAIRO_STATUS_SUCCESS ? save_png(surf, png_path, err)
                                        : sp_error_set(err, SP_E_IO, "%s: cairo: %s", png_path, cairo_status_to_string(st));
    cairo_surface_destroy(surf);
    return rc;
}
