/* The canvas on Cairo: an RGB24 image surface and its context. Shapes, images and text are
 * Cairo's; this file adds text layout (alignment, wrapping, ellipsis) and guards Cairo from bad
 * strings, since one invalid UTF-8 string puts a cairo_t into a permanent error state.
 * Compiled only when Cairo is found (nocairo/canvas.c otherwise). */
#include <cairo/cairo.h>
#include <stdlib.h>
#include <string.h>

#include "media/media_internal.h"
#include "semsplat/io.h"
#include "semsplat/media.h"

struct sp_canvas {
    int width, height;
    cairo_surface_t *surface;
    cairo_t *cr;
};

int sp_canvas_create(sp_canvas **out, int width, int height, sp_error *err)
{
    *out = NULL;
    if (width < 1 || height < 1 || width > MEDIA_MAX_SIDE || height > MEDIA_MAX_SIDE)
        return sp_error_set(err, SP_E_ARG, "canvas %dx%d: expected 1..%d pixels a side", width,
                            height, MEDIA_MAX_SIDE);
    sp_canvas *c = calloc(1, sizeof *c);
    if (!c) return sp_error_set(err, SP_E_NOMEM, "canvas %dx%d: out of memory", width, height);
    c->width = width;
    c->height = height;
    c->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    if (cairo_surface_status(c->surface) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(c->surface);
        free(c);
        return sp_error_set(err, SP_E_NOMEM, "canvas %dx%d: %s", width, height,
                            "Cairo could not allocate the surface");
    }
    c->cr = cairo_create(c->surface);
    if (cairo_status(c->cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(c->cr);
        cairo_surface_destroy(c->surface);
        free(c);
        return sp_error_set(err, SP_E_NOMEM, "canvas %dx%d: Cairo could not create a context",
                            width, height);
    }
    sp_canvas_clear(c, sp_rgba_of(1, 1, 1, 1));
    *out = c;
    return 0;
}

void sp_canvas_free(sp_canvas *c)
{
    if (!c) return;
    cairo_destroy(c->cr);
    cairo_surface_destroy(c->surface);
    free(c);
}

int sp_canvas_width(const sp_canvas *c) { return c->width; }
int sp_canvas_height(const sp_canvas *c) { return c->height; }

static void set_color(cairo_t *cr, sp_rgba k)
{
    cairo_set_source_rgba(cr, k.r, k.g, k.b, k.a);
}

static void fill_stroke(cairo_t *cr, sp_rgba fill, sp_rgba stroke, float line_px)
{
    if (fill.a > 0) {
        set_color(cr, fill);
        if (stroke.a > 0 && line_px > 0) cairo_fill_preserve(cr);
        else cairo_fill(cr);
    }
    if (stroke.a > 0 && line_px > 0) {
        set_color(cr, stroke);
        cairo_set_line_width(cr, line_px);
        cairo_stroke(cr);
    }
    cairo_new_path(cr);
}

void sp_canvas_clear(sp_canvas *c, sp_rgba color)
{
    cairo_save(c->cr);
    cairo_set_operator(c->cr, CAIRO_OPERATOR_SOURCE);
    set_color(c->cr, color);
    cairo_paint(c->cr);
    cairo_restore(c->cr);
}

void sp_canvas_rect(sp_canvas *c, float x, float y, float w, float h, sp_rgba fill,
                    sp_rgba stroke, float line_px)
{
    cairo_rectangle(c->cr, x, y, w, h);
    fill_stroke(c->cr, fill, stroke, line_px);
}

void sp_canvas_polyline(sp_canvas *c, const float *xy, int n, int closed, sp_rgba color,
                        float line_px)
{
    if (n < 2 || !xy) return;
    cairo_t *cr = c->cr;
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (int i = 0; i < n; i++) {
        if (!isfinite(xy[2 * i]) || !isfinite(xy[2 * i + 1])) continue;
        if (i == 0) cairo_move_to(cr, xy[0], xy[1]);
        else cairo_line_to(cr, xy[2 * i], xy[2 * i + 1]);
    }
    if (closed) cairo_close_path(cr);
    fill_stroke(cr, sp_rgba_of(0, 0, 0, 0), color, line_px);
}

void sp_canvas_circle(sp_canvas *c, float x, float y, float radius_px, sp_rgba fill,
                      sp_rgba stroke, float line_px)
{
    if (!(radius_px > 0)) return;
    cairo_new_sub_path(c->cr);
    cairo_arc(c->cr, x, y, radius_px, 0, 2 * M_PI);
    fill_stroke(c->cr, fill, stroke, line_px);
}

void sp_canvas_arrow(sp_canvas *c, float x0, float y0, float x1, float y1, sp_rgba color,
                     float line_px, float head_px)
{
    float dx = x1 - x0, dy = y1 - y0, L = sqrtf(dx * dx + dy * dy);
    if (!(L > 0)) return;
    float ux = dx / L, uy = dy / L, hl = fminf(head_px, L);
    float bx = x1 - ux * hl, by = y1 - uy * hl;
    float line[4] = {x0, y0, bx, by};
    sp_canvas_polyline(c, line, 2, 0, color, line_px);
    cairo_move_to(c->cr, x1, y1);
    cairo_line_to(c->cr, bx - uy * hl * 0.5f, by + ux * hl * 0.5f);
    cairo_line_to(c->cr, bx + uy * hl * 0.5f, by - ux * hl * 0.5f);
    cairo_close_path(c->cr);
    fill_stroke(c->cr, color, sp_rgba_of(0, 0, 0, 0), 0);
}

/* ---- images ----------------------------------------------------------------------------------- */

typedef uint8_t (*px_fn)(const void *src, size_t i);
static uint8_t px_u8(const void *src, size_t i) { return ((const uint8_t *)src)[i]; }
static uint8_t px_f32(const void *src, size_t i)
{
    float v = ((const float *)src)[i];
    if (!(v > 0)) return 0; /* NaN too */
    if (v >= 1) return 255;
    return (uint8_t)(v * 255.0f + 0.5f);
}

static int draw_image(sp_canvas *c, const void *src, px_fn px, int w, int h, float x, float y,
                      float bw, float bh, float placed[4], sp_error *err)
{
    if (!src || w < 1 || h < 1 || w > MEDIA_MAX_SIDE || h > MEDIA_MAX_SIDE)
        return sp_error_set(err, SP_E_ARG, "canvas image %dx%d: expected 1..%d pixels a side%s", w,
                            h, MEDIA_MAX_SIDE, src ? "" : " and pixels (got NULL)");
    if (!(bw > 0) || !(bh > 0))
        return sp_error_set(err, SP_E_ARG, "canvas image box %gx%g: expected a positive size",
                            bw, bh);
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return sp_error_set(err, SP_E_NOMEM, "canvas image %dx%d: out of memory", w, h);
    }
    cairo_surface_flush(img);
    uint8_t *data = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < h; j++) {
        uint32_t *row = (uint32_t *)(data + (size_t)j * stride);
        for (int i = 0; i < w; i++) {
            size_t k = ((size_t)j * w + i) * 3;
            row[i] = 0xff000000u | (uint32_t)px(src, k) << 16 | (uint32_t)px(src, k + 1) << 8 |
                     px(src, k + 2);
        }
    }
    cairo_surface_mark_dirty(img);
    double s = fmin(bw / w, bh / h);
    double dw = w * s, dh = h * s, dx = x + 0.5 * (bw - dw), dy = y + 0.5 * (bh - dh);
    cairo_t *cr = c->cr;
    cairo_save(cr);
    cairo_rectangle(cr, dx, dy, dw, dh);
    cairo_clip(cr);
    cairo_translate(cr, dx, dy);
    cairo_scale(cr, s, s);
    cairo_set_source_surface(cr, img, 0, 0);
    /* GOOD: box-filtered when shrinking, bilinear when enlarging; PAD: the edges take the border
     * pixels instead of fading into transparent black */
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
    if (placed) {
        placed[0] = (float)dx;
        placed[1] = (float)dy;
        placed[2] = (float)dw;
        placed[3] = (float)dh;
    }
    return 0;
}

int sp_canvas_image(sp_canvas *c, const uint8_t *rgb, int w, int h, float x, float y, float bw,
                    float bh, float placed[4], sp_error *err)
{
    return draw_image(c, rgb, px_u8, w, h, x, y, bw, bh, placed, err);
}

int sp_canvas_image_f32(sp_canvas *c, const float *rgb, int w, int h, float x, float y, float bw,
                        float bh, float placed[4], sp_error *err)
{
    return draw_image(c, rgb, px_f32, w, h, x, y, bw, bh, placed, err);
}

/* ---- text ------------------------------------------------------------------------------------- */

static void set_font(cairo_t *cr, const sp_text_style *s)
{
    cairo_select_font_face(cr, s->mono ? "DejaVu Sans Mono" : "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           s->bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, s->size_px > 0 ? s->size_px : 24);
}

static double width_of(void *ctx, const char *s, size_t n)
{
    cairo_t *cr = ctx;
    char buf[MEDIA_MAX_LINE + 1];
    if (n > MEDIA_MAX_LINE) n = MEDIA_MAX_LINE;
    memcpy(buf, s, n);
    buf[n] = 0;
    cairo_text_extents_t e;
    cairo_text_extents(cr, buf, &e);
    return e.x_advance;
}

static float draw_lines(sp_canvas *c, float x, float y, const sp_text_style *st, const char *text,
                        int draw, float *max_w)
{
    sp_text_style s = *st;
    if (!(s.size_px > 0)) s.size_px = 24;
    if (!(s.line_height > 0)) s.line_height = 1.3f;
    if (max_w) *max_w = 0;
    if (!text) return 0;
    cairo_t *cr = c->cr;
    cairo_save(cr);
    set_font(cr, &s);
    media_lines L;
    if (media_layout(text, s.wrap_px, s.max_lines, width_of, cr, &L)) {
        cairo_restore(cr);
        return 0;
    }
    sp_rgba col = s.color.a > 0 ? s.color : sp_rgba_of(0, 0, 0, 1);
    set_color(cr, col);
    for (int i = 0; i < L.n; i++) {
        double w = width_of(cr, L.line[i], strlen(L.line[i]));
        if (max_w && w > *max_w) *max_w = (float)w;
        if (!draw) continue;
        double lx = s.align == SP_ALIGN_CENTER ? x - 0.5 * w : s.align == SP_ALIGN_RIGHT ? x - w : x;
        cairo_move_to(cr, lx, y + i * s.size_px * s.line_height);
        cairo_show_text(cr, L.line[i]);
    }
    cairo_new_path(cr);
    cairo_restore(cr);
    float h = L.n * s.size_px * s.line_height;
    media_lines_free(&L);
    return h;
}

float sp_canvas_text(sp_canvas *c, float x, float y, const sp_text_style *s, const char *text)
{
    return draw_lines(c, x, y, s, text, 1, NULL);
}

float sp_canvas_text_measure(sp_canvas *c, const sp_text_style *s, const char *text, float *width)
{
    return draw_lines(c, 0, 0, s, text, 0, width);
}

/* ---- export ----------------------------------------------------------------------------------- */

void sp_canvas_rgb(const sp_canvas *c, uint8_t *rgb)
{
    cairo_surface_flush(c->surface);
    const uint8_t *data = cairo_image_surface_get_data(c->surface);
    int stride = cairo_image_surface_get_stride(c->surface);
    for (int j = 0; j < c->height; j++) {
        const uint32_t *row = (const uint32_t *)(data + (size_t)j * stride);
        uint8_t *o = rgb + (size_t)j * c->width * 3;
        for (int i = 0; i < c->width; i++) {
            o[3 * i] = (uint8_t)(row[i] >> 16);
            o[3 * i + 1] = (uint8_t)(row[i] >> 8);
            o[3 * i + 2] = (uint8_t)row[i];
        }
    }
}

int sp_canvas_write_png(const sp_canvas *c, const char *path, sp_error *err)
{
    uint8_t *rgb = malloc((size_t)c->width * c->height * 3);
    if (!rgb) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    sp_canvas_rgb(c, rgb);
    sp_image img = {.width = c->width, .height = c->height, .channels = 3, .bit_depth = 8, .data = rgb};
    int rc = sp_image_write_png(path, &img, err);
    free(rgb);
    return rc;
}
