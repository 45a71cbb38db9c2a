/* Heatmaps: calibrated relevancy of a rendered view in the Turbo colormap, blended over the
 * rendered RGB so a person sees where the queried thing is. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"

/* Turbo (Mikhailov, Google AI 2019): the published polynomial approximation. */
void sp_turbo(float t, float rgb[3])
{
    if (!(t >= 0)) t = 0;
    if (t > 1) t = 1;
    const double r4[6] = {0.13572138, 4.61539260, -42.66032258, 132.13108234, -152.94239396, 59.28637943};
    const double g4[6] = {0.09140261, 2.19418839, 4.84296658, -14.18503333, 4.27729857, 2.82956604};
    const double b4[6] = {0.10667330, 12.64194608, -60.58204836, 110.36276771, -89.90310912, 27.34824973};
    double p[6] = {1, t, t * t, t * t * t, t * t * t * t, t * t * t * t * t};
    double c[3] = {0, 0, 0};
    for (int i = 0; i < 6; i++) {
        c[0] += r4[i] * p[i];
        c[1] += g4[i] * p[i];
        c[2] += b4[i] * p[i];
    }
    for (int k = 0; k < 3; k++) rgb[k] = (float)(c[k] < 0 ? 0 : c[k] > 1 ? 1 : c[k]);
}

static uint8_t to_u8(float v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return (uint8_t)lrintf(v * 255.0f);
}

void sp_heatmap_overlay(const float *rgb, const float *relevancy, int width, int height,
                        uint8_t *out)
{
    size_t np = (size_t)width * height;
    for (size_t p = 0; p < np; p++) {
        const float *c = rgb + 3 * p;
        uint8_t *o = out + 3 * p;
        /* a dimmed, desaturated scene keeps the context readable; the colour map fades in with
         * relevancy above neutral (0.5), so weak relevancy stays close to the base */
        float g = 0.55f * (0.3f * c[0] + 0.59f * c[1] + 0.11f * c[2]);
        float t = (relevancy[p] - 0.5f) * 2.0f;
        t = t > 0 ? (t < 1 ? t : 1) : 0;
        float h[3];
        sp_turbo(t, h);
        float a = 0.85f * (t * 1.5f < 1 ? t * 1.5f : 1);
        for (int k = 0; k < 3; k++) o[k] = to_u8((1 - a) * (0.5f * g + 0.25f * c[k]) + a * h[k]);
    }
}

/* Renders are pinhole; a distorted view's heatmap is resampled into the photo's own pixels (each
 * undistorted by Newton iteration), so pixel (x, y) of the heatmap is pixel (x, y) of the image
 * it names. Photo pixels the pinhole render does not cover are black and neutral (0.5). */
static int to_photo_pixels(const sp_camera *cam, float *rgb, float *rel, sp_error *err)
{
    size_t np = (size_t)cam->width * cam->height;
    sp_camera pin = *cam;
    pin.distortion = SP_DIST_NONE;
    float *tmp = malloc(sizeof(float) * np * 3);
    uint8_t *mask = malloc(np);
    int rc = 0;
    if (!tmp || !mask) rc = sp_error_set(err, SP_E_NOMEM, "heatmap: out of memory resampling %dx%d", cam->width, cam->height);
    if (!rc) rc = sp_camera_remap_from_pinhole(&pin, rgb, 3, cam, tmp, NULL, err);
    if (!rc) {
        memcpy(rgb, tmp, sizeof(float) * np * 3);
        rc = sp_camera_remap_from_pinhole(&pin, rel, 1, cam, tmp, mask, err);
    }
    if (!rc)
        for (size_t p = 0; p < np; p++) rel[p] = mask[p] ? tmp[p] : 0.5f;
    free(tmp), free(mask);
    return rc;
}

int sem_heatmap(sp_query_engine *e, const sp_sem_scorer *sc, int v, sp_query_result *res,
                sp_error *err)
{
    if (v < 0 || (size_t)v >= e->n_cams)
        return sp_error_set(err, SP_E_ARG, "heatmap: view %d not in 0..%zu", v, e->n_cams);
    const sp_camera *cam = &e->cams[v];
    int W = cam->width, H = cam->height;
    size_t np = (size_t)W * H;
    (void)sc;
    float *rgb = malloc(sizeof(float) * np * 3), *rel = malloc(sizeof(float) * np),
          *raw = malloc(sizeof(float) * np);
    uint8_t *img = malloc(np * 3);
    int rc = 0;
    if (!rgb || !rel || !raw || !img) {
        rc = sp_error_set(err, SP_E_NOMEM, "heatmap: out of memory for %dx%d", W, H);
        goto done;
    }
    /* The per-Gaussian relevancy composited like a colour (2 channels, not D), over the RGB. */
    if ((rc = sem_render_scores(e, cam, raw, rel, rgb, err))) goto done;
    if (cam->distortion != SP_DIST_NONE && (rc = to_photo_pixels(cam, rgb, rel, err))) goto done;
    /* Stretch the visible relevancy to the full colour range when the query was found, so a
     * weak-but-real CLIP match still reads; a query that was not found is faded (cold). */
    float rmax = 0.5f;
    for (size_t p = 0; p < np; p++)
        if (rel[p] > rmax) rmax = rel[p];
    float scale = res->valid && rmax > 0.55f ? 0.5f / (rmax - 0.5f) : 1.0f;
    if (!res->valid) { /* not found: fade by how far the confidence is below the bar */
        float f = e->opts.min_confidence > 0 ? res->confidence / e->opts.min_confidence : 0.0f;
        f = f < 0 ? 0 : f > 1 ? 1 : f;
        scale = f * f;
    }
    float *shown = raw; /* reuse */
    for (size_t p = 0; p < np; p++) shown[p] = 0.5f + (rel[p] - 0.5f) * scale;
    sp_heatmap_overlay(rgb, shown, W, H, img);
    free(res->relevancy_image);
    free(res->relevancy);
    res->relevancy_image = img;
    res->relevancy = rel;
    img = NULL;
    rel = NULL;
    res->width = W;
    res->height = H;
    res->view_index = v;
    if (e->cam_names) snprintf(res->view_name, sizeof res->view_name, "%s", e->cam_names[v]);
    else snprintf(res->view_name, sizeof res->view_name, "view %d", v);
done:
    free(rgb), free(rel), free(raw), free(img);
    return rc;
}
