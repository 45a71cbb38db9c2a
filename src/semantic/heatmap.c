/* Heatmaps: calibrated relevancy of a rendered view in the Turbo colormap, blended over the
 * rendered RGB so a person sees where the queried thing is. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "overlay.h"
#include "sem_cuda.h"
#include "sem_internal.h"

void sp_heatmap_overlay(const float *rgb, const float *relevancy, int width, int height,
                        uint8_t *out)
{
    size_t np = (size_t)width * height;
    for (size_t p = 0; p < np; p++) sem_overlay_pixel(rgb + 3 * p, relevancy[p], out + 3 * p);
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

/* A query that was not found is faded (cold) by how far its confidence is below the bar. */
static float fade_scale(float confidence, float min_conf)
{
    float f = min_conf > 0 ? confidence / min_conf : 0.0f;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    return f * f;
}

/* Found: stretch the visible relevancy to the full colour range (sem_found_scale), so a
 * weak-but-real CLIP match still reads; else fade_scale. */
static float display_scale(const float *rel, size_t np, int found, float confidence, float min_conf)
{
    if (!found) return fade_scale(confidence, min_conf);
    float rmax = 0.5f;
    for (size_t p = 0; p < np; p++)
        if (rel[p] > rmax) rmax = rel[p];
    return sem_found_scale(rmax);
}

static int heatmap_host(sp_query_engine *e, const sp_camera *cam, int found, float confidence,
                        float min_confidence, uint8_t *img, float *rel_out, sp_query_stages *st,
                        sp_error *err)
{
    int W = cam->width, H = cam->height;
    size_t np = (size_t)W * H;
    float *rgb = malloc(sizeof(float) * np * 3), *rel = malloc(sizeof(float) * np),
          *raw = malloc(sizeof(float) * np);
    int rc = 0;
    if (!rgb || !rel || !raw) {
        rc = sp_error_set(err, SP_E_NOMEM, "heatmap: out of memory for %dx%d", W, H);
        goto done;
    }
    double t0 = sp_time_now();
    /* The per-Gaussian relevancy composited like a colour (2 channels, not D), over the RGB. */
    if ((rc = sem_render_scores(e, cam, raw, rel, rgb, err))) goto done;
    double t1 = sp_time_now();
    if (cam->distortion != SP_DIST_NONE && (rc = to_photo_pixels(cam, rgb, rel, err))) goto done;
    float scale = display_scale(rel, np, found, confidence, min_confidence);
    float *shown = raw; /* reuse */
    for (size_t p = 0; p < np; p++) shown[p] = 0.5f + (rel[p] - 0.5f) * scale;
    sp_heatmap_overlay(rgb, shown, W, H, img);
    if (rel_out) memcpy(rel_out, rel, sizeof(float) * np);
    if (st) st->hm_render = (t1 - t0) * 1e3, st->hm_colormap = (sp_time_now() - t1) * 1e3;
done:
    free(rgb), free(rel), free(raw);
    return rc;
}

/* The same on the device: scores scene updated there, RGB + scores rendered into device
 * buffers, relevancy and overlay coloured there, and only the image and the relevancy copied. */
static int heatmap_device(sp_query_engine *e, const sp_camera *cam, int found, float confidence,
                          float min_confidence, uint8_t *img, float *rel_out, sp_query_stages *st,
                          sp_error *err)
{
    size_t np = (size_t)cam->width * cam->height, fb = sizeof(float);
    double t0 = sp_time_now();
    int rc = sem_scores_scene(e, err);
    /* rgb [np][3], two [np][2], alpha, rel [np], max, then the image (bytes) */
    size_t o_two = sem_align64(np * 3), o_alpha = o_two + sem_align64(np * 2),
           o_rel = o_alpha + sem_align64(np), o_max = o_rel + sem_align64(np), o_img = o_max + 64,
           total = o_img + (np * 3 + fb - 1) / fb;
    if (!rc) rc = sp_device_scratch_reserve(e->dev, &e->hm_out, total * fb, err);
    if (rc) return rc;
    float *b = e->hm_out.ptr;
    uint8_t *d_img = (uint8_t *)(b + o_img);
    sp_render_request req = {.rgb = b, .features = b + o_two, .alpha = b + o_alpha, .on_device = 1};
    if ((rc = sp_render_views(e->raster, e->scores_scene, cam, 1, &req, err)) ||
        (rc = sp_device_sync(e->dev, err)))
        return rc;
    double t1 = sp_time_now();
    rc = sem_cuda_heatmap(e->dev, np, b, b + o_two, b + o_alpha, found,
                          fade_scale(confidence, min_confidence), d_img, b + o_rel, b + o_max, err);
    if (!rc) rc = sp_device_sync(e->dev, err);
    double t2 = sp_time_now();
    if (!rc) rc = sp_device_download(e->dev, img, d_img, np * 3, err);
    if (!rc && rel_out) rc = sp_device_download(e->dev, rel_out, b + o_rel, np * fb, err);
    if (st) {
        st->hm_render = (t1 - t0) * 1e3;
        st->hm_colormap = (t2 - t1) * 1e3;
        st->hm_copy = (sp_time_now() - t2) * 1e3;
    }
    return rc;
}

int sem_heatmap_render(sp_query_engine *e, const sp_camera *cam, int found, float confidence,
                       float min_confidence, int host_stages, uint8_t *img, float *rel_out,
                       sp_query_stages *st, sp_error *err)
{
    if (cam->width < 1 || cam->height < 1 || cam->width > 16384 || cam->height > 16384 ||
        !(cam->fx > 0) || !(cam->fy > 0))
        return sp_error_set(err, SP_E_ARG, "heatmap: camera %dx%d, fx %g, fy %g is not a usable pinhole",
                            cam->width, cam->height, (double)cam->fx, (double)cam->fy);
    /* distorted views are resampled through the lens on the host */
    if (sem_device_stages(e, host_stages) && cam->distortion == SP_DIST_NONE)
        return heatmap_device(e, cam, found, confidence, min_confidence, img, rel_out, st, err);
    return heatmap_host(e, cam, found, confidence, min_confidence, img, rel_out, st, err);
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
    int rc = sem_heatmap_render(e, cam, res->valid, res->confidence, th->opts->min_confidence,
                                th->opts->host_stages, img, rel, &res->ms_stage, err);
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
