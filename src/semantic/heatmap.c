/* Heatmaps: calibrated relevancy of a rendered view in the Turbo colormap, blended over the
 * rendered RGB so a person sees where the queried thing is. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sem_internal.h"

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

/* Stretch the visible relevancy to the full colour range when the query was found, so a
 * weak-but-real CLIP match still reads; a query that was not found is faded (cold). */
static float display_scale(const float *rel, size_t np, int found, float confidence, float min_conf)
{
    if (!found) { /* not found: fade by how far the confidence is below the bar */
        float f = min_conf > 0 ? confidence / min_conf : 0.0f;
        f = f < 0 ? 0 : f > 1 ? 1 : f;
        return f * f;
    }
    float rmax = 0.5f;
    for (size_t p = 0; p < np; p++)
        if (rel[p] > rmax) rmax = rel[p];
    return rmax > 0.55f ? 0.5f / (rmax - 0.5f) : 1.0f;
}

int sem_heatmap_render(sp_query_engine *e, const sp_camera *cam, int found, float confidence,
                       float min_confidence, uint8_t *img, float *rel_out, sp_error *err)
{
    if (cam->width < 1 || cam->height < 1 || cam->width > 16384 || cam->height > 16384 ||
        !(cam->fx > 0) || !(cam->fy > 0))
        return sp_error_set(err, SP_E_ARG, "heatmap: camera %dx%d, fx %g, fy %g is not a usable pinhole",
                            cam->width, cam->height, (double)cam->fx, (double)cam->fy);
    int W = cam->width, H = cam->height;
    size_t np = (size_t)W * H;
    float *rgb = malloc(sizeof(float) * np * 3), *rel = malloc(sizeof(float) * np),
          *raw = malloc(sizeof(float) * np);
    int rc = 0;
    if (!rgb || !rel || !raw) {
        rc = sp_error_set(err, SP_E_NOMEM, "heatmap: out of memory for %dx%d", W, H);
        goto done;
    }
    /* The per-Gaussian relevancy composited like a colour (2 channels, not D), over the RGB. */
    if ((rc = sem_render_scores(e, cam, raw, rel, rgb, err))) goto done;
    if (cam->distortion != SP_DIST_NONE && (rc = to_photo_pixels(cam, rgb, rel, err))) goto done;
    float scale = display_scale(rel, np, found, confidence, min_confidence);
    float *shown = raw; /* reuse */
    for (size_t p = 0; p < np; p++) shown[p] = 0.5f + (rel[p] - 0.5f) * scale;
    sp_heatmap_overlay(rgb, shown, W, H, img);
    if (rel_out) memcpy(rel_out, rel, sizeof(float) * np);
done:
    free(rgb), free(rel), free(raw);
    return rc;
}

int sem_heatmap(sp_query_engine *e, const sem_thresholds *th, int v, sp_query_result *res,
                sp_error *err)
{
    if (v < 0 || (size_t)v >= e->n_cams)
        return sp_error_set(err, SP_E_ARG, "heatmap: view %d not in 0..%zu", v, e->n_cams);
    const sp_camera *cam = &e->cams[v];
    size_t np = (size_t)cam->width * cam->height;
    uint8_t *img = malloc(np * 3);
    float *rel = malloc(sizeof(float) * np);
    if (!img || !rel) {
        free(img), free(rel);
        return sp_error_set(err, SP_E_NOMEM, "heatmap: out of memory for %dx%d", cam->width, cam->height);
    }
    int rc = sem_heatmap_render(e, cam, res->valid, res->confidence, th->opts->min_confidence, img, rel, err);
    if (rc) {
        free(img), free(rel);
        return rc;
    }
    free(res->relevancy_image);
    free(res->relevancy);
    res->relevancy_image = img;
    res->relevancy = rel;
    res->width = cam->width;
    res->height = cam->height;
    res->view_index = v;
    if (e->cam_names) snprintf(res->view_name, sizeof res->view_name, "%s", e->cam_names[v]);
    else snprintf(res->view_name, sizeof res->view_name, "view %d", v);
    return 0;
}
