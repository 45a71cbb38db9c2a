/* Title cards, captions and panel labels for the demo video and report figures, built from the
 * canvas calls. Sizes are fractions of the canvas height: at 720 lines the caption text is 24 px
 * and a title 54 px, which read on a laptop screen and in a browser's small player. */
#include <string.h>

#include "semsplat/media.h"

sp_rgba sp_media_palette(int i)
{
    /* Okabe & Ito (2008), colour-blind safe; yellow last, as it is weak on light maps. */
    static const float pal[8][3] = {
        {0.000f, 0.447f, 0.698f}, {0.835f, 0.369f, 0.000f}, {0.000f, 0.620f, 0.451f},
        {0.902f, 0.624f, 0.000f}, {0.800f, 0.475f, 0.655f}, {0.337f, 0.706f, 0.914f},
        {0.941f, 0.894f, 0.259f}, {0.400f, 0.400f, 0.400f}};
    if (i < 0) i = -i;
    const float *p = pal[i % 8];
    return sp_rgba_of(p[0], p[1], p[2], 1);
}

void sp_media_title_card(sp_canvas *c, const char *title, const char *subtitle,
                         const char *footer)
{
    float W = (float)sp_canvas_width(c), H = (float)sp_canvas_height(c);
    sp_canvas_clear(c, sp_rgba_of(0.07f, 0.09f, 0.13f, 1));
    sp_canvas_rect(c, 0, H * 0.30f, W, H * 0.006f, sp_media_palette(0), sp_rgba_of(0, 0, 0, 0), 0);
    sp_text_style ts = {.size_px = H * 0.075f, .color = sp_rgba_of(1, 1, 1, 1), .bold = 1,
                        .align = SP_ALIGN_CENTER, .wrap_px = W * 0.86f, .line_height = 1.2f,
                        .max_lines = 2};
    float y = H * 0.42f + ts.size_px * 0.4f;
    y += sp_canvas_text(c, W * 0.5f, y, &ts, title ? title : "");
    if (subtitle && *subtitle) {
        sp_text_style ss = {.size_px = H * 0.038f, .color = sp_rgba_of(0.80f, 0.84f, 0.90f, 1),
                            .align = SP_ALIGN_CENTER, .wrap_px = W * 0.80f, .max_lines = 4};
        sp_canvas_text(c, W * 0.5f, y + H * 0.03f, &ss, subtitle);
    }
    if (footer && *footer) {
        sp_text_style fs = {.size_px = H * 0.026f, .color = sp_rgba_of(0.60f, 0.65f, 0.72f, 1),
                            .align = SP_ALIGN_CENTER, .wrap_px = W * 0.9f, .max_lines = 2};
        sp_canvas_text(c, W * 0.5f, H * 0.92f, &fs, footer);
    }
}

float sp_media_caption(sp_canvas *c, const char *text)
{
    if (!text || !*text) return 0;
    float W = (float)sp_canvas_width(c), H = (float)sp_canvas_height(c);
    float pad = H * 0.018f;
    sp_text_style s = {.size_px = H * 0.033f, .color = sp_rgba_of(1, 1, 1, 1),
                       .wrap_px = W - 4 * pad, .max_lines = 3};
    float th = sp_canvas_text_measure(c, &s, text, NULL);
    float band = th + 2 * pad;
    sp_canvas_rect(c, 0, H - band, W, band, sp_rgba_of(0, 0, 0, 0.68f), sp_rgba_of(0, 0, 0, 0), 0);
    sp_canvas_text(c, 2 * pad, H - band + pad + s.size_px * 0.95f, &s, text);
    return band;
}

float sp_media_label(sp_canvas *c, float x, float y, float size_px, const char *text)
{
    if (!text || !*text) return 0;
    sp_text_style s = {.size_px = size_px > 0 ? size_px : 20, .color = sp_rgba_of(1, 1, 1, 1),
                       .bold = 1, .max_lines = 1};
    float w = 0, h = sp_canvas_text_measure(c, &s, text, &w), pad = s.size_px * 0.3f;
    sp_canvas_rect(c, x, y, w + 2 * pad, h + pad, sp_rgba_of(0, 0, 0, 0.6f), sp_rgba_of(0, 0, 0, 0), 0);
    sp_canvas_text(c, x + pad, y + pad * 0.5f + s.size_px * 0.95f, &s, text);
    return h + pad;
}
