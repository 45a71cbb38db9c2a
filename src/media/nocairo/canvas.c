/* Stand-in for cairo/canvas.c when Cairo is not found: no canvas can be created, so pictures,
 * plots, title cards and the demo video fail with a message naming the package. The drawing calls
 * are never reached with a canvas and do nothing. */
#include "semsplat/media.h"

int sp_canvas_create(sp_canvas **c, int width, int height, sp_error *err)
{
    *c = NULL;
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "drawing needs Cairo, which this build lacks: install libcairo2-dev "
                        "(scripts/install-deps.sh) and rebuild");
}

void sp_canvas_free(sp_canvas *c) { (void)c; }
int sp_canvas_width(const sp_canvas *c) { return 0; }
int sp_canvas_height(const sp_canvas *c) { return 0; }
void sp_canvas_clear(sp_canvas *c, sp_rgba color) { (void)c; }
void sp_canvas_rect(sp_canvas *c, float x, float y, float w, float h, sp_rgba fill, sp_rgba stroke,
                    float line_px) { (void)c; }
void sp_canvas_polyline(sp_canvas *c, const float *xy, int n, int closed, sp_rgba color,
                        float line_px) { (void)c; }
void sp_canvas_circle(sp_canvas *c, float x, float y, float radius_px, sp_rgba fill, sp_rgba stroke,
                      float line_px) { (void)c; }
void sp_canvas_arrow(sp_canvas *c, float x0, float y0, float x1, float y1, sp_rgba color,
                     float line_px, float head_px) { (void)c; }

int sp_canvas_image(sp_canvas *c, const uint8_t *rgb, int w, int h, float x, float y, float bw,
                    float bh, float placed[4], sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "drawing needs Cairo (libcairo2-dev)");
}

int sp_canvas_image_f32(sp_canvas *c, const float *rgb, int w, int h, float x, float y, float bw,
                        float bh, float placed[4], sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "drawing needs Cairo (libcairo2-dev)");
}

float sp_canvas_text(sp_canvas *c, float x, float y, const sp_text_style *s, const char *text)
{
    return 0;
}

float sp_canvas_text_measure(sp_canvas *c, const sp_text_style *s, const char *text, float *width)
{
    if (width) *width = 0;
    return 0;
}

void sp_canvas_rgb(const sp_canvas *c, uint8_t *rgb) { (void)c; }

int sp_canvas_write_png(const sp_canvas *c, const char *path, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "%s: drawing needs Cairo (libcairo2-dev)", path);
}
