/* Horizontal grouped bar charts for reports: a row per category (object, stage), a bar per series
 * (method, capture), values printed at the bar ends, misses drawn as a marker rather than left as
 * an empty row. Built from the canvas calls only. */
#include <stdio.h>
#include <string.h>

#include "semsplat/media.h"

#define PLOT_MAX_SERIES 8

static const sp_rgba NONE = {0, 0, 0, 0};
static const sp_rgba INK = {0.15f, 0.15f, 0.18f, 1};
static const sp_rgba GRID = {0.86f, 0.87f, 0.90f, 1};
static const sp_rgba MISS = {0.80f, 0.10f, 0.10f, 1};

static int check(const sp_plot_bars *p, sp_error *err)
{
    if (!p || p->n_categories < 1 || !p->categories)
        return sp_error_set(err, SP_E_ARG, "bar chart: no categories");
    if (p->n_series < 1 || p->n_series > PLOT_MAX_SERIES || !p->series)
        return sp_error_set(err, SP_E_ARG, "bar chart: %d series (expected 1..%d)", p ? p->n_series : 0,
                            PLOT_MAX_SERIES);
    for (int s = 0; s < p->n_series; s++)
        if (!p->series[s].values)
            return sp_error_set(err, SP_E_ARG, "bar chart: series %d (%s) has no values", s,
                                p->series[s].name ? p->series[s].name : "unnamed");
    if (!isfinite(p->x_max) || p->x_max < 0)
        return sp_error_set(err, SP_E_ARG, "bar chart: x_max %g: expected 0 (from the data) or more",
                            p->x_max);
    return 0;
}

/* A tick step of 1, 2, 2.5 or 5 times a power of ten giving about five ticks up to max. */
static double nice_step(double max)
{
    double raw = max / 5, p = pow(10, floor(log10(raw))), m = raw / p;
    double f = m <= 1 ? 1 : m <= 2 ? 2 : m <= 2.5 ? 2.5 : m <= 5 ? 5 : 10;
    return f * p;
}

static double axis_max(const sp_plot_bars *p)
{
    double mx = p->ref_value > 0 ? p->ref_value : 0;
    for (int s = 0; s < p->n_series; s++)
        for (int i = 0; i < p->n_categories; i++) {
            double v = p->series[s].values[i];
            if (isfinite(v) && v > mx) mx = v;
        }
    if (!(mx > 0)) return 1;
    double st = nice_step(mx);
    return ceil(mx / st - 1e-9) * st;
}

static void dashed_vline(sp_canvas *c, float x, float y0, float y1, sp_rgba col, float lw)
{
    float dash = lw * 4;
    for (float y = y0; y < y1; y += 2 * dash) {
        float seg[4] = {x, y, x, fminf(y + dash, y1)};
        sp_canvas_polyline(c, seg, 2, 0, col, lw);
    }
}

static float legend(sp_canvas *c, const sp_plot_bars *p, float x, float y, float w, float fs)
{
    if (p->n_series < 2) return 0;
    sp_text_style ls = {.size_px = fs * 0.9f, .color = INK, .max_lines = 1};
    float cx = x;
    for (int s = 0; s < p->n_series; s++) {
        const char *name = p->series[s].name ? p->series[s].name : "";
        float tw = 0;
        sp_canvas_text_measure(c, &ls, name, &tw);
        if (cx > x && cx + fs * 1.4f + tw > x + w) break; /* one line of legend */
        sp_rgba col = p->series[s].color.a > 0 ? p->series[s].color : sp_media_palette(s);
        sp_canvas_rect(c, cx, y + fs * 0.15f, fs * 0.9f, fs * 0.9f, col, NONE, 0);
        sp_canvas_text(c, cx + fs * 1.2f, y + fs * 0.95f, &ls, name);
        cx += fs * 1.2f + tw + fs * 1.5f;
    }
    return fs * 1.6f;
}

int sp_plot_bars_draw(sp_canvas *c, float x, float y, float w, float h, const sp_plot_bars *p,
                      sp_error *err)
{
    int rc = check(p, err);
    if (rc) return rc;
    if (!(w > 40) || !(h > 40))
        return sp_error_set(err, SP_E_ARG, "bar chart: box %gx%g is too small", w, h);
    float fs = fminf(fmaxf(w / 55, 11), 20), pad = fs * 0.6f;
    float top = y + pad;
    if (p->title && *p->title) {
        sp_text_style ts = {.size_px = fs * 1.25f, .color = INK, .bold = 1, .wrap_px = w - 2 * pad,
                            .max_lines = 2};
        top += sp_canvas_text(c, x + pad, top + ts.size_px, &ts, p->title);
    }
    top += legend(c, p, x + pad, top + pad * 0.5f, w - 2 * pad, fs) + pad * 0.5f;
    float bottom = y + h - pad - fs * 1.4f * (p->x_label && *p->x_label ? 2 : 1);
    int nc = p->n_categories;
    float row = (bottom - top) / nc;
    if (!(row > 2))
        return sp_error_set(err, SP_E_ARG, "bar chart: %d rows do not fit %g pixels", nc, h);
    sp_text_style cs = {.size_px = fminf(fs, row * 0.75f), .color = INK, .align = SP_ALIGN_RIGHT,
                        .max_lines = 1};
    float label_w = 0;
    for (int i = 0; i < nc; i++) {
        float lw = 0;
        sp_canvas_text_measure(c, &cs, p->categories[i] ? p->categories[i] : "", &lw);
        if (lw > label_w) label_w = lw;
    }
    /* labels wider than 40% of the chart: a smaller font (down to 70%), then an ellipsis */
    float cap = w * 0.4f;
    if (label_w > cap) {
        float shrink = fmaxf(cap / label_w, 0.7f);
        cs.size_px *= shrink;
        label_w = fminf(label_w * shrink, cap);
        cs.wrap_px = cap;
    }
    float px0 = x + pad + label_w + pad, px1 = x + w - pad - fs * 3.5f;
    double xmax = p->x_max > 0 ? p->x_max : axis_max(p), step = nice_step(xmax);
    /* grid and tick labels */
    sp_text_style tk = {.size_px = fs * 0.85f, .color = INK, .align = SP_ALIGN_CENTER, .max_lines = 1};
    const char *fmt = p->value_format ? p->value_format : "%.2f";
    for (int k = 0; k * step <= xmax * (1 + 1e-9); k++) {
        float gx = px0 + (float)(k * step / xmax) * (px1 - px0);
        float gl[4] = {gx, top, gx, bottom};
        sp_canvas_polyline(c, gl, 2, 0, k ? GRID : INK, k ? 1 : 1.5f);
        char t[64];
        snprintf(t, sizeof t, fmt, k * step);
        sp_canvas_text(c, gx, bottom + fs * 1.1f, &tk, t);
    }
    if (p->x_label && *p->x_label) {
        sp_text_style xs = tk;
        xs.size_px = fs * 0.95f;
        sp_canvas_text(c, 0.5f * (px0 + px1), bottom + fs * 2.5f, &xs, p->x_label);
    }
    /* rows */
    int ns = p->n_series;
    float bar = row * 0.78f / ns;
    sp_text_style vs = {.size_px = fminf(fs * 0.8f, bar * 0.95f + 1), .color = INK, .max_lines = 1};
    for (int i = 0; i < nc; i++) {
        float ry = top + i * row;
        sp_canvas_text(c, px0 - pad, ry + row * 0.5f + cs.size_px * 0.35f, &cs,
                       p->categories[i] ? p->categories[i] : "");
        for (int s = 0; s < ns; s++) {
            const sp_plot_series *se = &p->series[s];
            sp_rgba col = se->color.a > 0 ? se->color : sp_media_palette(s);
            float by = ry + row * 0.11f + s * bar;
            double v = se->values[i];
            if (se->missed && se->missed[i]) {
                float m = bar * 0.35f, cx = px0 + m + 2, cy = by + bar * 0.5f;
                float a[4] = {cx - m, cy - m, cx + m, cy + m}, b[4] = {cx - m, cy + m, cx + m, cy - m};
                sp_canvas_polyline(c, a, 2, 0, MISS, 2);
                sp_canvas_polyline(c, b, 2, 0, MISS, 2);
                sp_text_style ms = vs;
                ms.color = MISS;
                sp_canvas_text(c, cx + m + 4, cy + vs.size_px * 0.35f, &ms, "missed");
                continue;
            }
            if (!isfinite(v)) continue;
            float len = (float)(fmax(v, 0) / xmax) * (px1 - px0);
            if (len > px1 - px0) len = px1 - px0;
            sp_canvas_rect(c, px0, by, len, bar * 0.92f, col, NONE, 0);
            char t[64];
            snprintf(t, sizeof t, fmt, v);
            sp_canvas_text(c, px0 + len + 4, by + bar * 0.46f + vs.size_px * 0.35f, &vs, t);
        }
    }
    if (p->ref_value > 0 && p->ref_value <= xmax) {
        float rx = px0 + (float)(p->ref_value / xmax) * (px1 - px0);
        dashed_vline(c, rx, top, bottom, MISS, 1.5f);
        if (p->ref_label && *p->ref_label) {
            sp_text_style rs = {.size_px = fs * 0.8f, .color = MISS, .align = SP_ALIGN_CENTER, .max_lines = 1};
            sp_canvas_text(c, rx, top - fs * 0.2f, &rs, p->ref_label);
        }
    }
    return 0;
}

int sp_plot_bars_png(const char *path, int width, int height, const sp_plot_bars *p,
                     sp_error *err)
{
    int rc = check(p, err);
    if (rc) return rc;
    sp_canvas *c;
    if ((rc = sp_canvas_create(&c, width, height, err))) return rc;
    rc = sp_plot_bars_draw(c, 0, 0, (float)width, (float)height, p, err);
    if (!rc) rc = sp_canvas_write_png(c, path, err);
    sp_canvas_free(c);
    return rc;
}
