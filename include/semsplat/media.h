/* semsplat media: the pictures and the video that reports and the demo show.
 *
 * - sp_canvas: an RGB picture drawn with Cairo (Debian's libcairo2): fills, rectangles, lines,
 *   circles, images scaled into a box, and text (DejaVu Sans / Sans Mono through fontconfig,
 *   aligned, wrapped to a width). Title cards and captions are built from these, sized so they
 *   read at 1280x720. A canvas exports as 8-bit RGB or as a PNG (written atomically).
 * - sp_plot_bars: horizontal grouped bar charts (per-object localization errors with misses
 *   marked, success rate per stage), drawn onto a canvas or written as a PNG.
 * - sp_video: an H.264 MP4 writer through FFmpeg's libraries (libavcodec with libx264,
 *   libavformat, libswscale): 8-bit RGB frames in, YUV 4:2:0 out at a fixed frame rate. The file
 *   is written to <path>.tmp.<pid> and renamed to path by sp_video_close, so a reader never sees
 *   a half-written video; sp_video_discard removes it instead.
 *
 * Both libraries are optional: without Cairo the canvas and plots fail with SP_E_UNSUPPORTED
 * naming libcairo2-dev, without FFmpeg's libraries the video writer names them.
 * Ownership: sp_canvas and sp_video are opaque handles created and freed by this module; buffers
 * passed in stay the caller's. A canvas or a video is used by one thread at a time. */
#ifndef SEMSPLAT_MEDIA_H
#define SEMSPLAT_MEDIA_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A colour with alpha, each in [0,1]. */
typedef struct sp_rgba { float r, g, b, a; } sp_rgba;

static inline sp_rgba sp_rgba_of(float r, float g, float b, float a)
{
    sp_rgba c = {r, g, b, a};
    return c;
}

/* A distinct colour for series / paths i = 0, 1, 2, ... (a qualitative palette, Okabe-Ito). */
sp_rgba sp_media_palette(int i);

/* ---- canvas ----------------------------------------------------------------------------------- */

typedef struct sp_canvas sp_canvas;

/* A canvas of width x height pixels (1..8192 each), cleared to opaque white. */
int sp_canvas_create(sp_canvas **c, int width, int height, sp_error *err);
void sp_canvas_free(sp_canvas *c);
int sp_canvas_width(const sp_canvas *c);
int sp_canvas_height(const sp_canvas *c);

void sp_canvas_clear(sp_canvas *c, sp_rgba color);
/* Axis-aligned rectangle in pixels (y down); fill and/or stroke (alpha 0 = none). */
void sp_canvas_rect(sp_canvas *c, float x, float y, float w, float h, sp_rgba fill,
                    sp_rgba stroke, float line_px);
/* Polyline through xy [n][2] pixels; closed joins the last point to the first. */
void sp_canvas_polyline(sp_canvas *c, const float *xy, int n, int closed, sp_rgba color,
                        float line_px);
void sp_canvas_circle(sp_canvas *c, float x, float y, float radius_px, sp_rgba fill,
                      sp_rgba stroke, float line_px);
/* An arrow from (x0, y0) to (x1, y1) with a filled head of head_px. */
void sp_canvas_arrow(sp_canvas *c, float x0, float y0, float x1, float y1, sp_rgba color,
                     float line_px, float head_px);

/* Draws an RGB image (rgb [h][w][3], 8-bit, rows top first) scaled to fit inside the box
 * (x, y, bw, bh), keeping its aspect ratio, centred in the box, with bilinear filtering.
 * Writes the drawn rectangle into placed[4] (x, y, w, h; may be NULL). */
int sp_canvas_image(sp_canvas *c, const uint8_t *rgb, int w, int h, float x, float y, float bw,
                    float bh, float placed[4], sp_error *err);
/* The same from float RGB in [0,1] (a renderer's output). */
int sp_canvas_image_f32(sp_canvas *c, const float *rgb, int w, int h, float x, float y, float bw,
                        float bh, float placed[4], sp_error *err);

typedef enum { SP_ALIGN_LEFT = 0, SP_ALIGN_CENTER = 1, SP_ALIGN_RIGHT = 2 } sp_text_align;

typedef struct sp_text_style {
    float size_px;     /* font size (em) in pixels; 0 = 24 */
    sp_rgba color;     /* alpha 0 = opaque black */
    int bold;
    int mono;          /* DejaVu Sans Mono instead of DejaVu Sans */
    int align;         /* sp_text_align, relative to x */
    float wrap_px;     /* > 0: break lines at spaces to fit this width ('\n' always breaks) */
    float line_height; /* line advance as a multiple of size_px; 0 = 1.3 */
    int max_lines;     /* > 0: stop after this many lines, ending the last with "..." */
} sp_text_style;

/* Draws text with its first baseline at y - so the top of the first line is about
 * y - 0.8 * size_px - and returns the height the lines take (lines * size_px * line_height).
 * UTF-8; non-printable bytes are shown as '?'. */
float sp_canvas_text(sp_canvas *c, float x, float y, const sp_text_style *s, const char *text);
/* Height the same call would take, and the widest line's width (may be NULL), without drawing. */
float sp_canvas_text_measure(sp_canvas *c, const sp_text_style *s, const char *text,
                             float *width);

/* Copies the canvas into rgb [height][width][3]. */
void sp_canvas_rgb(const sp_canvas *c, uint8_t *rgb);
/* Writes the canvas as an 8-bit RGB PNG, atomically. */
int sp_canvas_write_png(const sp_canvas *c, const char *path, sp_error *err);

/* ---- title cards and captions (sized for legibility at 1280x720, scaled by the height) -------- */

/* The whole canvas: dark background, the title large and centred, the subtitle below it, a
 * smaller footer line near the bottom (subtitle and footer may be NULL). */
void sp_media_title_card(sp_canvas *c, const char *title, const char *subtitle,
                         const char *footer);
/* A band along the bottom edge, dark and translucent, with the text in white, wrapped to at
 * most three lines. Returns the band's height in pixels. */
float sp_media_caption(sp_canvas *c, const char *text);
/* A label with a translucent dark box behind it, at (x, y) = its top-left corner; returns the
 * box's height. For panel headings over images. */
float sp_media_label(sp_canvas *c, float x, float y, float size_px, const char *text);

/* ---- plots ------------------------------------------------------------------------------------ */

/* One series of a bar chart: values[n_categories] (NaN = no bar). missed (may be NULL): 1 draws
 * a marker with the word "missed" where the bar would be, so a miss is not an empty row. */
typedef struct sp_plot_series {
    const char *name;
    const double *values;
    const uint8_t *missed;
    sp_rgba color; /* alpha 0 = sp_media_palette(series index) */
} sp_plot_series;

/* Horizontal grouped bars: one row per category (top to bottom), one bar per series in a row,
 * the value printed at the end of each bar, the x axis from 0 to x_max with ticks and a grid. */
typedef struct sp_plot_bars {
    const char *title;              /* drawn at the top (may be NULL) */
    const char *x_label;            /* under the axis, e.g. "error (m)" */
    int n_categories;
    const char *const *categories;  /* row labels */
    int n_series;                   /* 1..8 */
    const sp_plot_series *series;
    double x_max;                   /* 0: from the data (rounded up to a tick) */
    const char *value_format;       /* printf format for one double; NULL = "%.2f" */
    double ref_value;               /* > 0: a dashed vertical line at this value ... */
    const char *ref_label;          /* ... labelled with this (may be NULL) */
} sp_plot_bars;

/* Draws the chart inside the box (x, y, w, h) of c. Fails with SP_E_ARG on no categories, a bad
 * series count, a NULL values array, or a negative or non-finite x_max. */
int sp_plot_bars_draw(sp_canvas *c, float x, float y, float w, float h, const sp_plot_bars *p,
                      sp_error *err);
/* The chart alone as a PNG of width x height pixels on white, written atomically. */
int sp_plot_bars_png(const char *path, int width, int height, const sp_plot_bars *p,
                     sp_error *err);

/* ---- how useful a rendered view is (no reference image needed) ---------------------------------- */

/* Blur anchors of sp_media_view_quality, measured on synth's camera images (not on any
 * evaluation result): 28 frames of a house drive at 640x480 read 0.314 on average, the same
 * frames under a further Gaussian blur of 1 px 0.534, of 2 px 0.726, of 3 px 0.834. So a render
 * as sharp as the camera scores sharpness 1 and one 2 px softer 0. The measure depends on
 * content (a world of flat-coloured boxes reads 0.41 when sharp): it grades views for a report,
 * it is not a verdict on one picture. */
#define SP_BLUR_SHARP 0.31
#define SP_BLUR_BLURRY 0.73

typedef struct sp_view_quality {
    double coverage;  /* fraction of pixels the splat covers (alpha >= 0.5; 1 without alpha) */
    double blur;      /* no-reference blur of the covered pixels' luminance (Crete, Dolmiere,
                         Ladret, Nicolas 2007: how much a 9-tap box re-blur removes of the
                         neighbour differences; 0 sharp .. 1 flat); 1 when nothing is covered */
    double sharpness; /* (SP_BLUR_BLURRY - blur) / (SP_BLUR_BLURRY - SP_BLUR_SHARP), in [0, 1] */
    double score;     /* 1 + 4 * coverage * sharpness: 1 (nothing useful) .. 5 (covered, sharp) */
    int grade;        /* score rounded, 1..5 */
} sp_view_quality;

/* Measures a rendered view: rgb [h][w][3] in [0,1], alpha [h][w] (may be NULL). Fails with
 * SP_E_ARG on sizes under 16x16 or NULL pixels, SP_E_NUMERIC on non-finite values. */
int sp_media_view_quality(const float *rgb, const float *alpha, int w, int h, sp_view_quality *q,
                          sp_error *err);

/* ---- video ------------------------------------------------------------------------------------ */

typedef struct sp_video sp_video;

typedef struct sp_video_opts {
    int width, height; /* even, 16..8192; 0,0 = 1280x720 */
    int fps;           /* 1..120; 0 = 25 */
    int crf;           /* x264 constant rate factor 0..51; 0 = 23 */
    const char *preset;/* x264 preset; NULL = "veryfast" */
    int threads;       /* encoder threads; 0 = 2 */
} sp_video_opts;

/* Opens an H.264 MP4 for writing at <path>.tmp.<pid>. Fails with SP_E_UNSUPPORTED when this
 * build has no FFmpeg libraries or FFmpeg has no H.264 encoder, SP_E_ARG on bad options,
 * SP_E_IO when the file cannot be created. */
int sp_video_open(sp_video **v, const char *path, const sp_video_opts *o, sp_error *err);
/* Appends one frame (rgb [height][width][3], 8-bit, the size given at open), repeat times (a
 * card held for a few seconds; repeat >= 1). */
int sp_video_frame(sp_video *v, const uint8_t *rgb, int repeat, sp_error *err);
/* The same from a canvas of the video's size. */
int sp_video_frame_canvas(sp_video *v, const sp_canvas *c, int repeat, sp_error *err);
/* Frames written so far, and the frame rate. */
long sp_video_frames(const sp_video *v);
int sp_video_fps(const sp_video *v);
/* Flushes the encoder, writes the MP4 index and renames the file to its final path; frees v
 * whatever happens (on error the temporary file is removed). */
int sp_video_close(sp_video *v, sp_error *err);
/* Stops writing, removes the temporary file and frees v (NULL is fine). */
void sp_video_discard(sp_video *v);

#ifdef __cplusplus
}
#endif
#endif
