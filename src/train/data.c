/* Training data: a COLMAP model and its images turned into pinhole views with 8-bit RGB, the
 * held-out split, the scene extent, and gsplat's two initialisations (from points3D with
 * nearest-neighbour scales, or random in a cube). */
#include "semsplat/io.h"
#include "train/train_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int view_cmp(const void *a, const void *b)
{
    return strcmp(((const sp_train_view *)a)->name, ((const sp_train_view *)b)->name);
}

void sp_train_data_update_scene(sp_train_data *d)
{
    double c[3] = {0, 0, 0};
    for (size_t i = 0; i < d->n_views; i++) {
        sp_vec3 p = sp_camera_center(&d->views[i].cam);
        c[0] += p.x, c[1] += p.y, c[2] += p.z;
    }
    size_t n = d->n_views ? d->n_views : 1;
    d->scene_center = sp_v3((float)(c[0] / n), (float)(c[1] / n), (float)(c[2] / n));
    float m = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        float r = sp_v3_norm(sp_v3_sub(sp_camera_center(&d->views[i].cam), d->scene_center));
        if (r > m) m = r;
    }
    d->scene_scale = m > 0 ? m : 1.0f;
}

/* Box-filter downscale of an 8-bit RGB image by an integer factor. */
static uint8_t *downscale_rgb(const uint8_t *src, int W, int H, int f, int *ow, int *oh)
{
    int w = W / f, h = H / f;
    uint8_t *dst = malloc((size_t)w * h * 3);
    if (!dst) return NULL;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                unsigned sum = 0;
                for (int dy = 0; dy < f; dy++)
                    for (int dx = 0; dx < f; dx++)
                        sum += src[((size_t)(y * f + dy) * W + (x * f + dx)) * 3 + c];
                dst[((size_t)y * w + x) * 3 + c] = (uint8_t)((sum + (unsigned)(f * f) / 2) / (unsigned)(f * f));
            }
    *ow = w;
    *oh = h;
    return dst;
}

/* Where output pixel (x, y) of the pinhole camera with focal lengths (fx', fy') = s * (fx, fy)
 * samples the distorted image. */
static void undistort_source(const sp_camera *c, double s, double x, double y, double *sx, double *sy)
{
    double u = (x + 0.5 - c->cx) / (s * c->fx), v = (y + 0.5 - c->cy) / (s * c->fy), du, dv;
    sp_camera_distort(c, u, v, &du, &dv);
    *sx = du * c->fx + c->cx - 0.5;
    *sy = dv * c->fy + c->cy - 0.5;
}

/* Resamples a distorted image into a pinhole one of the same size and principal point, with the
 * focal length scaled (as COLMAP's undistorter) so that every output pixel sees image content:
 * the largest s in [0.25, 4] for which the whole output border maps inside the source. */
static int undistort_view(sp_train_view *v, sp_error *err)
{
    sp_camera *c = &v->cam;
    int W = c->width, H = c->height;
    double lo = 0.25, hi = 4.0;
    for (int it = 0; it < 40; it++) {
        double s = 0.5 * (lo + hi);
        int inside = 1;
        for (int k = 0; k < 2 * (W + H) && inside; k++) {
            double x, y, sx, sy;
            if (k < W) x = k, y = 0;
            else if (k < 2 * W) x = k - W, y = H - 1;
            else if (k < 2 * W + H) x = 0, y = k - 2 * W;
            else x = W - 1, y = k - 2 * W - H;
            undistort_source(c, s, x, y, &sx, &sy);
            inside = sx >= 0 && sy >= 0 && sx <= W - 1 && sy <= H - 1;
        }
        /* a larger focal length shows less, so inside-ness grows with s */
        if (inside) hi = s;
        else lo = s;
    }
    double s = hi;
    uint8_t *out = malloc((size_t)W * H * 3);
    if (!out) return sp_error_set(err, SP_E_NOMEM, "undistorting %s: out of memory", v->name);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double sx, sy;
            undistort_source(c, s, x, y, &sx, &sy);
            if (sx < 0) sx = 0;
            if (sy < 0) sy = 0;
            if (sx > W - 1) sx = W - 1;
            if (sy > H - 1) sy = H - 1;
            int x0 = (int)sx, y0 = (int)sy, x1 = x0 + 1 < W ? x0 + 1 : x0, y1 = y0 + 1 < H ? y0 + 1 : y0;
            double fx = sx - x0, fy = sy - y0;
            for (int ch = 0; ch < 3; ch++) {
                double a = v->rgb[((size_t)y0 * W + x0) * 3 + ch], b = v->rgb[((size_t)y0 * W + x1) * 3 + ch];
                double cc = v->rgb[((size_t)y1 * W + x0) * 3 + ch], d = v->rgb[((size_t)y1 * W + x1) * 3 + ch];
                double val = (1 - fy) * ((1 - fx) * a + fx * b) + fy * ((1 - fx) * cc + fx * d);
                out[((size_t)y * W + x) * 3 + ch] = (uint8_t)(val + 0.5);
            }
        }
    free(v->rgb);
    v->rgb = out;
    c->fx = (float)(c->fx * s);
    c->fy = (float)(c->fy * s);
    c->distortion = SP_DIST_NONE;
    memset(c->dist, 0, sizeof c->dist);
    return SP_OK;
}

/* Any sp_image (grey/RGB/RGBA, 8/16 bit) to packed 8-bit RGB. */
static uint8_t *image_to_rgb8(const sp_image *img)
{
    size_t n = (size_t)img->width * img->height;
    uint8_t *out = malloc(n * 3);
    if (!out) return NULL;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3; c++) {
            int sc = img->channels >= 3 ? c : 0;
            size_t k = p * img->channels + sc;
            out[p * 3 + c] = img->bit_depth == 16 ? (uint8_t)(((const uint16_t *)img->data)[k] >> 8)
                                                  : ((const uint8_t *)img->data)[k];
        }
    return out;
}

int sp_train_data_load(sp_train_data *d, const char *colmap_dir, const char *images_dir,
                       int downscale, int test_every, sp_error *err)
{
    memset(d, 0, sizeof *d);
    if (downscale < 1 || downscale > 64)
        return sp_error_set(err, SP_E_ARG, "downscale factor %d is outside 1..64", downscale);
    if (test_every < 0) return sp_error_set(err, SP_E_ARG, "test_every %d must be >= 0 (0: no held-out views)", test_every);
    char imdir[4096];
    if (images_dir) snprintf(imdir, sizeof imdir, "%s", images_dir);
    else if (sp_path_join(imdir, sizeof imdir, colmap_dir, "images"))
        return sp_error_set(err, SP_E_ARG, "%s: path too long", colmap_dir);
    sp_colmap_model m;
    int rc = sp_colmap_read(colmap_dir, &m, err);
    if (rc) return rc;
    if (m.n_images == 0) {
        sp_colmap_free(&m);
        return sp_error_set(err, SP_E_FORMAT, "%s: the COLMAP model has no images", colmap_dir);
    }
    /* Check every image exists before reading any, so the message lists the first missing one
     * and how many are missing. */
    size_t missing = 0, first_missing = 0;
    for (size_t i = 0; i < m.n_images; i++) {
        char p[4096];
        sp_path_join(p, sizeof p, imdir, m.images[i].name);
        if (!sp_file_exists(p) && missing++ == 0) first_missing = i;
    }
    if (missing) {
        rc = sp_error_set(err, SP_E_NOTFOUND,
                          "%s: image '%s' named by the COLMAP model is missing (%zu of %zu images "
                          "missing); does --images point at the right folder?",
                          imdir, m.images[first_missing].name, missing, m.n_images);
        sp_colmap_free(&m);
        return rc;
    }
    d->views = calloc(m.n_images, sizeof(sp_train_view));
    if (!d->views) {
        sp_colmap_free(&m);
        return sp_error_set(err, SP_E_NOMEM, "out of memory for %zu views", m.n_images);
    }
    for (size_t i = 0; i < m.n_images; i++) {
        sp_train_view *v = &d->views[d->n_views];
        const sp_colmap_image *ci = &m.images[i];
        snprintf(v->name, sizeof v->name, "%s", ci->name);
        if ((rc = sp_colmap_image_camera(&m, i, &v->cam, err))) {
            /* fisheye and other models sp_camera cannot carry */
            const sp_colmap_camera *cc = sp_colmap_find_camera(&m, ci->camera_id);
            const char *model = cc ? sp_colmap_model_name(cc->model) : NULL;
            if (rc == SP_E_UNSUPPORTED)
                sp_error_set(err, rc,
                             "%s: image '%s' uses camera %u with a %s lens model, which semsplat "
                             "cannot undistort (it handles PINHOLE, SIMPLE_PINHOLE and the radial "
                             "/ OPENCV distortion models): run `colmap image_undistorter` first "
                             "and train on its output",
                             colmap_dir, ci->name, ci->camera_id, model ? model : "unknown");
            goto fail;
        }
        char p[4096];
        sp_path_join(p, sizeof p, imdir, ci->name);
        sp_image img;
        if ((rc = sp_image_read(p, &img, err))) goto fail;
        /* Images may be stored smaller than the camera (images_2/ etc.): accept a uniform ratio. */
        if (img.width != v->cam.width || img.height != v->cam.height) {
            double rx = (double)v->cam.width / img.width, ry = (double)v->cam.height / img.height;
            if (fabs(rx - ry) > 0.02 * rx) {
                rc = sp_error_set(err, SP_E_FORMAT,
                                  "%s: image is %dx%d but its COLMAP camera %u is %dx%d: the "
                                  "model does not match the images folder",
                                  p, img.width, img.height, ci->camera_id, v->cam.width,
                                  v->cam.height);
                sp_image_free(&img);
                goto fail;
            }
            v->cam.fx /= (float)rx, v->cam.cx /= (float)rx;
            v->cam.fy /= (float)ry, v->cam.cy /= (float)ry;
            v->cam.width = img.width, v->cam.height = img.height;
        }
        uint8_t *rgb = image_to_rgb8(&img);
        sp_image_free(&img);
        if (!rgb) {
            rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", p);
            goto fail;
        }
        if (v->cam.distortion != SP_DIST_NONE) {
            v->rgb = rgb;
            if ((rc = undistort_view(v, err))) goto fail;
            rgb = v->rgb;
            v->rgb = NULL;
            v->undistorted = 1;
            d->n_undistorted++;
        }
        if (downscale > 1) {
            int w, h;
            uint8_t *small = downscale_rgb(rgb, v->cam.width, v->cam.height, downscale, &w, &h);
            free(rgb);
            if (!small) {
                rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", p);
                goto fail;
            }
            rgb = small;
            sp_camera_downscale(&v->cam, downscale);
        }
        if (v->cam.width < SP_SSIM_WINDOW || v->cam.height < SP_SSIM_WINDOW) {
            free(rgb);
            rc = sp_error_set(err, SP_E_ARG, "%s: %dx%d after downscaling is too small to train on",
                              p, v->cam.width, v->cam.height);
            goto fail;
        }
        v->rgb = rgb;
        d->n_views++;
    }
    qsort(d->views, d->n_views, sizeof(sp_train_view), view_cmp);
    for (size_t i = 0; i < d->n_views; i++)
        d->views[i].is_test = test_every > 0 && (i % (size_t)test_every) == 0 && d->n_views > 1;
    if (m.n_points) {
        d->points = malloc(m.n_points * 3 * sizeof(float));
        d->point_rgb = malloc(m.n_points * 3);
        if (!d->points || !d->point_rgb) {
            rc = sp_error_set(err, SP_E_NOMEM, "out of memory for %zu points", m.n_points);
            goto fail;
        }
        for (size_t i = 0; i < m.n_points; i++)
            for (int a = 0; a < 3; a++) {
                d->points[i * 3 + a] = (float)m.points[i].xyz[a];
                d->point_rgb[i * 3 + a] = m.points[i].rgb[a];
            }
        d->n_points = m.n_points;
    }
    sp_colmap_free(&m);
    sp_train_data_update_scene(d);
    return SP_OK;
fail:
    sp_colmap_free(&m);
    sp_train_data_free(d);
    return rc;
}

void sp_train_data_free(sp_train_data *d)
{
    if (!d) return;
    for (size_t i = 0; i < d->n_views; i++) {
        free(d->views[i].rgb);
        free(d->views[i].depth);
    }
    free(d->views);
    free(d->points);
    free(d->point_rgb);
    memset(d, 0, sizeof *d);
}

/* ---- depth targets ------------------------------------------------------------------------------ */

/* depth_dir/<stem of name>.npy */
static int depth_path(char *out, size_t cap, const char *dir, const char *name)
{
    char stem[256];
    snprintf(stem, sizeof stem, "%s", name);
    char *dot = strrchr(stem, '.'), *slash = strrchr(stem, '/');
    if (dot && (!slash || dot > slash)) *dot = 0;
    int n = snprintf(out, cap, "%s/%s.npy", dir, stem);
    return n < 0 || (size_t)n >= cap;
}

/* Block mean of the valid (> 0) samples; 0 where fewer than half of a block are valid. */
static float *downscale_depth(const float *src, int W, int f, int w, int h)
{
    float *dst = malloc((size_t)w * h * sizeof(float));
    if (!dst) return NULL;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double sum = 0;
            int n = 0;
            for (int dy = 0; dy < f; dy++)
                for (int dx = 0; dx < f; dx++) {
                    float z = src[(size_t)(y * f + dy) * W + (x * f + dx)];
                    if (z > 0) sum += z, n++;
                }
            dst[(size_t)y * w + x] = 2 * n >= f * f ? (float)(sum / n) : 0.0f;
        }
    return dst;
}

/* Reads one view's depth file into v->depth (checked: [h][w] of the image, finite, >= 0). */
static int load_view_depth(sp_train_view *v, const char *path, int downscale, sp_error *err)
{
    sp_npy a;
    int rc = sp_npy_read(path, &a, err);
    if (rc) return rc;
    int w = v->cam.width, h = v->cam.height;
    int ok_shape = (a.ndim == 2 || (a.ndim == 3 && a.shape[2] == 1)) &&
                   a.shape[0] / (size_t)downscale == (size_t)h && a.shape[1] / (size_t)downscale == (size_t)w;
    if (!ok_shape) {
        rc = sp_error_set(err, SP_E_FORMAT,
                          "%s: depth of shape %s[%zu][%zu] does not match image '%s' (%dx%d before "
                          "a downscale of %d: needs [%d][%d])",
                          path, a.ndim == 2 || a.ndim == 3 ? "" : "(not 2-D) ", a.shape[0],
                          a.ndim > 1 ? a.shape[1] : 0, v->name, w * downscale, h * downscale, downscale,
                          h * downscale, w * downscale);
        sp_npy_free(&a);
        return rc;
    }
    float *z = NULL;
    size_t W0 = a.shape[1], n = a.shape[0] * W0;
    rc = sp_npy_to_f32(&a, &z, err);
    sp_npy_free(&a);
    if (rc) return sp_error_prefix(err, "%s: ", path);
    for (size_t i = 0; i < n; i++)
        if (!(z[i] >= 0) || !isfinite(z[i])) {
            rc = sp_error_set(err, SP_E_FORMAT, "%s: depth %g at pixel (%zu, %zu) (must be finite and "
                              ">= 0; 0 = no measurement)", path, (double)z[i], i % W0, i / W0);
            free(z);
            return rc;
        }
    if (downscale > 1) {
        float *small = downscale_depth(z, (int)W0, downscale, w, h);
        free(z);
        if (!small) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
        z = small;
    }
    free(v->depth);
    v->depth = z;
    return SP_OK;
}

int sp_train_data_load_depth(sp_train_data *d, const char *depth_dir, int downscale,
                             size_t *n_loaded, const sp_log *log, sp_error *err)
{
    if (n_loaded) *n_loaded = 0;
    if (downscale < 1 || downscale > 64)
        return sp_error_set(err, SP_E_ARG, "downscale factor %d is outside 1..64", downscale);
    if (!depth_dir || !sp_file_exists(depth_dir))
        return sp_error_set(err, SP_E_NOTFOUND, "depth supervision: no depth folder %s (a synth "
                            "capture writes depth/NNNNN.npy beside images/)", depth_dir ? depth_dir : "(none)");
    size_t loaded = 0, missing = 0, first_missing = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        sp_train_view *v = &d->views[i];
        char path[4400];
        if (depth_path(path, sizeof path, depth_dir, v->name))
            return sp_error_set(err, SP_E_ARG, "%s: path too long", depth_dir);
        if (!sp_file_exists(path)) {
            if (missing++ == 0) first_missing = i;
            continue;
        }
        if (v->undistorted)
            return sp_error_set(err, SP_E_UNSUPPORTED, "%s: view '%s' was undistorted at load time; "
                                "depth supervision needs pinhole views (undistort the depth too, or "
                                "train without --depth-lambda)", path, v->name);
        int rc = load_view_depth(v, path, downscale, err);
        if (rc) return rc;
        loaded++;
    }
    if (loaded == 0)
        return sp_error_set(err, SP_E_NOTFOUND, "depth supervision: %s has none of the %zu views' "
                            "depth files (e.g. for '%s')", depth_dir, d->n_views,
                            d->n_views ? d->views[0].name : "");
    if (missing)
        sp_logf(log, SP_LOG_WARN, "depth: %zu of %zu views have no depth file in %s (first: '%s'); "
                "their depth term is skipped", missing, d->n_views, depth_dir, d->views[first_missing].name);
    if (n_loaded) *n_loaded = loaded;
    return SP_OK;
}

/* ---- nearest neighbours on a uniform grid ------------------------------------------------------ */

typedef struct {
    uint64_t key;
    uint32_t idx;
} grid_entry;

static int entry_cmp(const void *a, const void *b)
{
    uint64_t x = ((const grid_entry *)a)->key, y = ((const grid_entry *)b)->key;
    return x < y ? -1 : x > y;
}

/* Mean distance from each point to its 3 nearest other points (gsplat: sqrt of the mean squared
 * distance to the 3 nearest). */
static int knn3_scale(const float *p, size_t n, float *out, sp_error *err)
{
    if (n < 2) {
        for (size_t i = 0; i < n; i++) out[i] = 0.01f;
        return SP_OK;
    }
    float lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            if (p[i * 3 + a] < lo[a]) lo[a] = p[i * 3 + a];
            if (p[i * 3 + a] > hi[a]) hi[a] = p[i * 3 + a];
        }
    double vol = 1;
    for (int a = 0; a < 3; a++) vol *= (hi[a] - lo[a]) + 1e-6;
    float cell = (float)cbrt(vol * 4.0 / (double)n);
    int dim[3];
    for (int a = 0; a < 3; a++) {
        if (cell <= 0) cell = 1e-3f;
        dim[a] = (int)((hi[a] - lo[a]) / cell) + 1;
        if (dim[a] > 1500) dim[a] = 1500;
    }
    float cs[3];
    for (int a = 0; a < 3; a++) cs[a] = ((hi[a] - lo[a]) + 1e-6f) / dim[a];
    grid_entry *e = malloc(n * sizeof *e);
    if (!e) return sp_error_set(err, SP_E_NOMEM, "init: out of memory for %zu points", n);
#define CELL(i, a) ((int)((p[(i) * 3 + (a)] - lo[a]) / cs[a]) >= dim[a] ? dim[a] - 1 : (int)((p[(i) * 3 + (a)] - lo[a]) / cs[a]))
#define KEY(x, y, z) (((uint64_t)(x) * (uint64_t)dim[1] + (uint64_t)(y)) * (uint64_t)dim[2] + (uint64_t)(z))
    for (size_t i = 0; i < n; i++) e[i] = (grid_entry){KEY(CELL(i, 0), CELL(i, 1), CELL(i, 2)), (uint32_t)i};
    qsort(e, n, sizeof *e, entry_cmp);
    float minc = cs[0] < cs[1] ? (cs[0] < cs[2] ? cs[0] : cs[2]) : (cs[1] < cs[2] ? cs[1] : cs[2]);
    for (size_t i = 0; i < n; i++) {
        int c[3] = {CELL(i, 0), CELL(i, 1), CELL(i, 2)};
        float best[3] = {INFINITY, INFINITY, INFINITY};
        for (int r = 0;; r++) {
            /* visit the shell of cells at Chebyshev distance r */
            for (int dx = -r; dx <= r; dx++)
                for (int dy = -r; dy <= r; dy++)
                    for (int dz = -r; dz <= r; dz++) {
                        if (abs(dx) != r && abs(dy) != r && abs(dz) != r) continue;
                        int x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
                        if (x < 0 || y < 0 || z < 0 || x >= dim[0] || y >= dim[1] || z >= dim[2]) continue;
                        uint64_t k = KEY(x, y, z);
                        size_t a = 0, b = n;
                        while (a < b) {
                            size_t mid = (a + b) / 2;
                            if (e[mid].key < k) a = mid + 1;
                            else b = mid;
                        }
                        for (; a < n && e[a].key == k; a++) {
                            size_t j = e[a].idx;
                            if (j == i) continue;
                            float d0 = p[j * 3] - p[i * 3], d1 = p[j * 3 + 1] - p[i * 3 + 1],
                                  d2 = p[j * 3 + 2] - p[i * 3 + 2];
                            float dd = d0 * d0 + d1 * d1 + d2 * d2;
                            if (dd < best[2]) {
                                if (dd < best[1]) {
                                    best[2] = best[1];
                                    if (dd < best[0]) best[1] = best[0], best[0] = dd;
                                    else best[1] = dd;
                                } else best[2] = dd;
                            }
                        }
                    }
            /* every unvisited point is at least r * min cell size away */
            float reach = r * minc;
            int maxr = dim[0] > dim[1] ? (dim[0] > dim[2] ? dim[0] : dim[2]) : (dim[1] > dim[2] ? dim[1] : dim[2]);
            if ((isfinite(best[2]) && best[2] <= reach * reach) || r > maxr) break;
        }
        int k = isfinite(best[2]) ? 3 : isfinite(best[1]) ? 2 : 1;
        float s = 0;
        for (int q = 0; q < k; q++) s += best[q];
        out[i] = sqrtf(s / k);
        if (!(out[i] > 1e-7f)) out[i] = 1e-7f;
    }
#undef CELL
#undef KEY
    free(e);
    return SP_OK;
}

static int init_common(sp_splat *s, const float *pts, const float *rgb01, size_t n, int sh_degree,
                       uint64_t seed, sp_error *err)
{
    int rc = sp_splat_alloc(s, n, sh_degree, 0, err);
    if (rc) return rc;
    float *dist = malloc((n ? n : 1) * sizeof(float));
    if (!dist) {
        sp_splat_free(s);
        return sp_error_set(err, SP_E_NOMEM, "init: out of memory");
    }
    if ((rc = knn3_scale(pts, n, dist, err))) {
        free(dist);
        sp_splat_free(s);
        return rc;
    }
    uint64_t rng = tr_seed(seed);
    size_t K = (size_t)sp_sh_coeffs(sh_degree);
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < 3; a++) {
            s->means[i * 3 + a] = pts[i * 3 + a];
            s->log_scales[i * 3 + a] = logf(dist[i]);
            s->sh[i * K * 3 + a] = (rgb01[i * 3 + a] - 0.5f) / SP_SH_C0;
        }
        for (int a = 0; a < 4; a++) s->quats[i * 4 + a] = (float)tr_uniform(&rng);
        s->opacity_logits[i] = sp_logit(0.1f);
    }
    free(dist);
    return SP_OK;
}

int sp_train_init_from_points(sp_splat *s, const sp_train_data *d, int sh_degree, uint64_t seed,
                              sp_error *err)
{
    if (d->n_points == 0 || !d->points)
        return sp_error_set(err, SP_E_ARG,
                            "init: the COLMAP model has no 3D points; use random init (--init random)");
    float *rgb = malloc(d->n_points * 3 * sizeof(float));
    if (!rgb) return sp_error_set(err, SP_E_NOMEM, "init: out of memory");
    for (size_t i = 0; i < d->n_points * 3; i++) rgb[i] = d->point_rgb[i] / 255.0f;
    int rc = init_common(s, d->points, rgb, d->n_points, sh_degree, seed, err);
    free(rgb);
    return rc;
}

int sp_train_init_random(sp_splat *s, const sp_train_data *d, size_t n, float extent,
                         int sh_degree, uint64_t seed, sp_error *err)
{
    if (n == 0 || n > (size_t)1 << 30)
        return sp_error_set(err, SP_E_ARG, "init: random init points %zu outside 1..2^30", n);
    float *pts = malloc(n * 3 * sizeof(float)), *rgb = malloc(n * 3 * sizeof(float));
    if (!pts || !rgb) {
        free(pts);
        free(rgb);
        return sp_error_set(err, SP_E_NOMEM, "init: out of memory for %zu points", n);
    }
    uint64_t rng = tr_seed(seed ^ 0xabcdefULL);
    float half = extent * d->scene_scale, c[3] = {d->scene_center.x, d->scene_center.y, d->scene_center.z};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            pts[i * 3 + a] = c[a] + half * (float)(2 * tr_uniform(&rng) - 1);
            rgb[i * 3 + a] = (float)tr_uniform(&rng);
        }
    int rc = init_common(s, pts, rgb, n, sh_degree, seed, err);
    free(pts);
    free(rgb);
    return rc;
}
