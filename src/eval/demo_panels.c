/* Panels of the demo video: a picture file in a box, the top-down map of the costmap with the
 * plan, the driven trail and the robot, and the text panel of the agent's tool calls. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_video.h"
#include "semsplat/io.h"

static const sp_rgba WHITE = {1, 1, 1, 1}, NONE = {0, 0, 0, 0};

/* A PNG/JPEG from disk into the box (a grey box saying so when it cannot be read). */
int dv_image_file(sp_canvas *c, const char *path, float x, float y, float w, float h, sp_error *err)
{
    sp_image img = {0};
    sp_error e = {0};
    if (!path || !path[0] || sp_image_read(path, &img, &e) || img.bit_depth != 8 || img.channels < 3) {
        sp_image_free(&img);
        sp_canvas_rect(c, x, y, w, h, sp_rgba_of(0.3f, 0.3f, 0.32f, 1), NONE, 0);
        sp_text_style st = {.size_px = 20, .color = WHITE, .align = SP_ALIGN_CENTER, .wrap_px = w - 20};
        sp_canvas_text(c, x + w / 2, y + h / 2, &st, path && path[0] ? "(image not readable)" : "(no image)");
        return SP_OK;
    }
    int rc = SP_OK;
    uint8_t *rgb = img.data;
    uint8_t *packed = NULL;
    if (img.channels != 3) { /* drop alpha */
        packed = malloc((size_t)img.width * img.height * 3);
        if (!packed) rc = sp_error_set(err, SP_E_NOMEM, "demo: out of memory");
        for (size_t i = 0; packed && i < (size_t)img.width * img.height; i++)
            memcpy(packed + 3 * i, (uint8_t *)img.data + (size_t)img.channels * i, 3);
        rgb = packed;
    }
    if (!rc) rc = sp_canvas_image(c, rgb, img.width, img.height, x, y, w, h, NULL, err);
    free(packed);
    sp_image_free(&img);
    return rc;
}

int dv_map_init(dv_map *m, const sp_costmap *cm, sp_error *err)
{
    memset(m, 0, sizeof *m);
    m->cm = cm;
    m->rgb = malloc((size_t)cm->nx * cm->ny * 3);
    if (!m->rgb) return sp_error_set(err, SP_E_NOMEM, "demo: out of memory for the map");
    for (int iy = 0; iy < cm->ny; iy++)
        for (int ix = 0; ix < cm->nx; ix++) {
            uint8_t o = cm->occ[(size_t)iy * cm->nx + ix];
            uint8_t v[3] = {246, 246, 242};
            if (o == SP_CELL_OCCUPIED) v[0] = v[1] = v[2] = 40;
            else if (o == SP_CELL_UNKNOWN) v[0] = 150, v[1] = 156, v[2] = 170;
            memcpy(m->rgb + 3 * ((size_t)(cm->ny - 1 - iy) * cm->nx + ix), v, 3); /* +y up */
        }
    return SP_OK;
}

void dv_map_free(dv_map *m)
{
    free(m->rgb);
    memset(m, 0, sizeof *m);
}

static void to_px(const dv_map *m, double x, double y, float *px, float *py)
{
    const sp_costmap *cm = m->cm;
    *px = m->placed[0] + (float)((x - cm->origin[0]) / cm->res) * m->placed[2] / (float)cm->nx;
    *py = m->placed[1] + m->placed[3] - (float)((y - cm->origin[1]) / cm->res) * m->placed[3] / (float)cm->ny;
}

int dv_map_draw(sp_canvas *c, dv_map *m, float x, float y, float w, float h, sp_error *err)
{
    return sp_canvas_image(c, m->rgb, m->cm->nx, m->cm->ny, x, y, w, h, m->placed, err);
}

/* A polyline of xy pairs (stride doubles apart) in world metres. */
void dv_map_path(sp_canvas *c, const dv_map *m, const double *xy, int n, int stride, sp_rgba color, float line_px)
{
    if (n < 2) return;
    float *pts = malloc(sizeof(float) * 2 * (size_t)n);
    if (!pts) return;
    for (int i = 0; i < n; i++) to_px(m, xy[stride * i], xy[stride * i + 1], &pts[2 * i], &pts[2 * i + 1]);
    sp_canvas_polyline(c, pts, n, 0, color, line_px);
    free(pts);
}

void dv_map_robot(sp_canvas *c, const dv_map *m, double x, double y, double yaw)
{
    float px, py, ax, ay;
    to_px(m, x, y, &px, &py);
    to_px(m, x + 0.45 * cos(yaw), y + 0.45 * sin(yaw), &ax, &ay);
    sp_canvas_circle(c, px, py, 9, sp_rgba_of(0.85f, 0.1f, 0.1f, 1), WHITE, 2);
    sp_canvas_arrow(c, px, py, ax, ay, sp_rgba_of(0.85f, 0.1f, 0.1f, 1), 3, 10);
}

void dv_map_marker(sp_canvas *c, const dv_map *m, double x, double y, sp_rgba color, const char *label)
{
    float px, py;
    to_px(m, x, y, &px, &py);
    sp_canvas_circle(c, px, py, 8, NONE, color, 3);
    if (label) {
        sp_text_style st = {.size_px = 18, .bold = 1, .color = color};
        sp_canvas_text(c, px + 11, py - 8, &st, label);
    }
}

/* The tool calls of both answers as a monospaced list under a heading. */
void dv_tools_panel(sp_canvas *c, const char *heading, const char *const *blocks, const char *const *labels, int n)
{
    int W = sp_canvas_width(c), H = sp_canvas_height(c);
    float s = (float)H / 720.0f;
    sp_canvas_clear(c, sp_rgba_of(0.09f, 0.10f, 0.13f, 1));
    sp_text_style hs = {.size_px = 34 * s, .bold = 1, .color = WHITE};
    float y = 70 * s;
    y += sp_canvas_text(c, 50 * s, y, &hs, heading) + 10 * s;
    sp_text_style ls = {.size_px = 24 * s, .bold = 1, .color = sp_rgba_of(0.55f, 0.8f, 1, 1), .wrap_px = (float)W - 100 * s};
    sp_text_style ms = {.size_px = 20 * s, .mono = 1, .color = sp_rgba_of(0.9f, 0.95f, 0.85f, 1),
                        .wrap_px = (float)W - 130 * s, .max_lines = 9};
    for (int i = 0; i < n; i++) {
        y += 14 * s;
        y += sp_canvas_text(c, 50 * s, y, &ls, labels[i]) + 4 * s;
        y += sp_canvas_text(c, 80 * s, y, &ms, blocks[i] && blocks[i][0] ? blocks[i] : "(no tool calls)");
    }
}
