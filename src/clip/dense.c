/* Image preprocessing (CLIP's resize + centre crop + normalise) and dense text-aligned feature
 * maps: the image is resized by each scale, cut into overlapping tiles at the model's input size,
 * each tile goes through the dense head (one feature per patch), overlapping patches are averaged
 * and the scales are resampled onto the first scale's grid and averaged. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip_internal.h"

/* PIL's bicubic filter (a = -0.5), which CLIPImageProcessor resamples with. */
static double bicubic_filter(double x)
{
    const double a = -0.5;
    x = fabs(x);
    if (x < 1) return ((a + 2) * x - (a + 3)) * x * x + 1;
    if (x < 2) return (((x - 5) * x + 8) * x - 4) * a;
    return 0;
}

/* Resampling weights of one axis as PIL's ImagingResample: output i samples around
 * (i + 0.5) * in/out with the filter stretched by the downscale factor (antialiasing), weights
 * normalised (clip_internal.h: clip_axis_weights). */
int clip_axis_weights_make(clip_axis_weights *a, int n_in, int n_out)
{
    double scale = (double)n_in / n_out, fs = scale > 1 ? scale : 1, support = 2 * fs;
    a->taps = (int)ceil(support) * 2 + 1;
    a->w = malloc((size_t)n_out * a->taps * sizeof *a->w);
    a->x0 = malloc((size_t)n_out * 2 * sizeof *a->x0);
    if (!a->w || !a->x0) {
        free(a->w);
        free(a->x0);
        return -1;
    }
    a->cnt = a->x0 + n_out;
    for (int i = 0; i < n_out; i++) {
        double center = (i + 0.5) * scale;
        int lo = (int)(center - support + 0.5), hi = (int)(center + support + 0.5);
        if (lo < 0) lo = 0;
        if (hi > n_in) hi = n_in;
        if (hi - lo > a->taps) hi = lo + a->taps;
        double sum = 0, *wi = a->w + (size_t)i * a->taps;
        for (int k = lo; k < hi; k++) sum += (wi[k - lo] = bicubic_filter((k - center + 0.5) / fs));
        for (int k = lo; k < hi; k++) wi[k - lo] /= sum != 0 ? sum : 1;
        a->x0[i] = lo;
        a->cnt[i] = hi - lo;
    }
    return 0;
}

void clip_axis_weights_free(clip_axis_weights *a)
{
    free(a->w);
    free(a->x0);
}

/* Resizes an interleaved [h][w][3] image to [oh][ow][3]: horizontal pass, then a vertical pass
 * that combines whole rows (contiguous memory). */
static int resize_rgb(const float *in, int w, int h, float *out, int ow, int oh)
{
    clip_axis_weights ax, ay;
    float *tmp = malloc((size_t)h * ow * 3 * sizeof *tmp);
    double *acc = malloc((size_t)ow * 3 * sizeof *acc);
    if (!tmp || !acc || clip_axis_weights_make(&ax, w, ow)) {
        free(tmp);
        free(acc);
        return -1;
    }
    if (clip_axis_weights_make(&ay, h, oh)) {
        clip_axis_weights_free(&ax);
        free(tmp);
        free(acc);
        return -1;
    }
    for (int y = 0; y < h; y++)
        for (int i = 0; i < ow; i++) {
            const double *wi = ax.w + (size_t)i * ax.taps;
            const float *src = in + ((size_t)y * w + ax.x0[i]) * 3;
            double s0 = 0, s1 = 0, s2 = 0;
            for (int k = 0; k < ax.cnt[i]; k++) {
                s0 += wi[k] * src[3 * k];
                s1 += wi[k] * src[3 * k + 1];
                s2 += wi[k] * src[3 * k + 2];
            }
            float *o = tmp + ((size_t)y * ow + i) * 3;
            o[0] = (float)s0;
            o[1] = (float)s1;
            o[2] = (float)s2;
        }
    size_t row = (size_t)ow * 3;
    for (int i = 0; i < oh; i++) {
        const double *wi = ay.w + (size_t)i * ay.taps;
        memset(acc, 0, row * sizeof *acc);
        for (int k = 0; k < ay.cnt[i]; k++) {
            const float *src = tmp + (size_t)(ay.x0[i] + k) * row;
            for (size_t j = 0; j < row; j++) acc[j] += wi[k] * src[j];
        }
        for (size_t j = 0; j < row; j++) out[(size_t)i * row + j] = (float)acc[j];
    }
    clip_axis_weights_free(&ax);
    clip_axis_weights_free(&ay);
    free(tmp);
    free(acc);
    return 0;
}

int sp_clip_preprocess(const sp_clip *c, const float *rgb, int width, int height, float *pixels,
                       sp_error *err)
{
    int S = c->cfg.image_size;
    if (width < 1 || height < 1)
        return sp_error_set(err, SP_E_ARG, "preprocess: image size %dx%d", width, height);
    /* resize so the shortest side is S (the other side truncated as transformers does) */
    int rw, rh;
    if (width <= height) { rw = S; rh = (int)((long)S * height / width); }
    else { rh = S; rw = (int)((long)S * width / height); }
    if (rw < S) rw = S;
    if (rh < S) rh = S;
    float *r = malloc((size_t)rw * rh * 3 * sizeof *r);
    if (!r || resize_rgb(rgb, width, height, r, rw, rh)) {
        free(r);
        return sp_error_set(err, SP_E_NOMEM, "preprocess: out of memory");
    }
    int top = (rh - S) / 2, left = (rw - S) / 2;
    for (int ch = 0; ch < 3; ch++)
        for (int y = 0; y < S; y++)
            for (int x = 0; x < S; x++) {
                float v = r[((size_t)(y + top) * rw + x + left) * 3 + ch];
                pixels[((size_t)ch * S + y) * S + x] = (v - c->cfg.image_mean[ch]) / c->cfg.image_std[ch];
            }
    free(r);
    return 0;
}

int sp_clip_encode_image(sp_clip *c, const float *rgb, int n, int width, int height, float *out,
                         sp_error *err)
{
    int S = c->cfg.image_size;
    float *px = malloc((size_t)n * 3 * S * S * sizeof *px);
    if (!px) return sp_error_set(err, SP_E_NOMEM, "encode_image: out of memory");
    int rc = 0;
    for (int i = 0; i < n && !rc; i++)
        rc = sp_clip_preprocess(c, rgb + (size_t)i * width * height * 3, width, height,
                                px + (size_t)i * 3 * S * S, err);
    if (!rc) rc = sp_clip_encode_pixels(c, px, n, S, S, out, err);
    free(px);
    return rc;
}

/* ---- dense ------------------------------------------------------------------------------------- */

sp_clip_dense_opts sp_clip_dense_opts_default(void)
{
    sp_clip_dense_opts o;
    memset(&o, 0, sizeof o);
    o.head = SP_CLIP_HEAD_CLEARCLIP;
    o.scales[0] = 2.0f;
    o.n_scales = 1;
    o.batch = 8;
    return o;
}

void clip_plan_scale(const sp_clip *c, float s, int tile, int width, int height, clip_scale_plan *sp)
{
    int p = c->cfg.patch_size;
    sp->rw = (int)lroundf(width * s);
    sp->rh = (int)lroundf(height * s);
    if (sp->rw < 1) sp->rw = 1;
    if (sp->rh < 1) sp->rh = 1;
    sp->gw = (sp->rw + p - 1) / p;
    sp->gh = (sp->rh + p - 1) / p;
    sp->pw = sp->gw * p < tile ? tile : sp->gw * p;
    sp->ph = sp->gh * p < tile ? tile : sp->gh * p;
}

void clip_tile_params(const sp_clip *c, const sp_clip_dense_opts *o, int *tile, int *stride)
{
    int p = c->cfg.patch_size;
    *tile = o->tile > 0 ? o->tile / p * p : c->cfg.image_size;
    if (*tile < p) *tile = p;
    *stride = o->stride > 0 ? o->stride / p * p : *tile / 2 / p * p;
    if (*stride < p) *stride = p;
}

void sp_clip_dense_grid(const sp_clip *c, const sp_clip_dense_opts *o, int width, int height,
                        int *grid_w, int *grid_h)
{
    sp_clip_dense_opts d = o ? *o : sp_clip_dense_opts_default();
    int tile, stride;
    clip_tile_params(c, &d, &tile, &stride);
    clip_scale_plan sp;
    clip_plan_scale(c, d.n_scales > 0 ? d.scales[0] : 1.f, tile, width, height, &sp);
    *grid_w = sp.gw;
    *grid_h = sp.gh;
}

/* Tile origins along one axis: 0, stride, ... and the last one flush with the end. Returns the
 * count, of which only the first cap are written (cap 0: count only). */
int clip_tile_starts(int padded, int tile, int stride, int *out, int cap)
{
    int n = 0;
    for (int x = 0;; x += stride, n++) {
        int last = x + tile >= padded;
        if (n < cap) out[n] = last ? padded - tile : x;
        if (last) return n + 1;
    }
}

/* Dense features of one scale into acc [gh][gw][P] (summed) + cnt [gh][gw]. */
static int dense_scale(sp_clip *c, const float *rgb, int width, int height, const clip_scale_plan *sp,
                       int tile, int stride, clip_out_kind kind, int batch, float *acc, float *cnt,
                       sp_error *err)
{
    int p = c->cfg.patch_size, P = c->cfg.projection_dim, tg = tile / p;
    float *img = malloc((size_t)sp->rw * sp->rh * 3 * sizeof *img);
    float *norm = calloc((size_t)sp->pw * sp->ph * 3, sizeof *norm);
    float *px = malloc((size_t)batch * 3 * tile * tile * sizeof *px);
    float *feat = malloc((size_t)batch * tg * tg * P * sizeof *feat);
    int xs[CLIP_TILES_MAX], ys[CLIP_TILES_MAX];
    int nx = clip_tile_starts(sp->pw, tile, stride, xs, CLIP_TILES_MAX);
    int ny = clip_tile_starts(sp->ph, tile, stride, ys, CLIP_TILES_MAX);
    int rc = 0;
    if (!img || !norm || !px || !feat || nx > CLIP_TILES_MAX || ny > CLIP_TILES_MAX ||
        resize_rgb(rgb, width, height, img, sp->rw, sp->rh)) {
        rc = sp_error_set(err, SP_E_NOMEM, "dense features: out of memory for %dx%d", sp->rw, sp->rh);
        goto done;
    }
    /* normalised planar image; padding stays 0 = the mean colour */
    for (int ch = 0; ch < 3; ch++)
        for (int y = 0; y < sp->rh; y++)
            for (int x = 0; x < sp->rw; x++)
                norm[((size_t)ch * sp->ph + y) * sp->pw + x] =
                    (img[((size_t)y * sp->rw + x) * 3 + ch] - c->cfg.image_mean[ch]) / c->cfg.image_std[ch];
    long n_tiles = (long)nx * ny;
    for (long t0 = 0; t0 < n_tiles && !rc; t0 += batch) {
        int nb = (int)(n_tiles - t0 < batch ? n_tiles - t0 : batch);
        for (int b = 0; b < nb; b++) {
            int tx = xs[(t0 + b) % nx], ty = ys[(t0 + b) / nx];
            for (int ch = 0; ch < 3; ch++)
                for (int y = 0; y < tile; y++)
                    memcpy(px + (((size_t)b * 3 + ch) * tile + y) * tile,
                           norm + ((size_t)ch * sp->ph + ty + y) * sp->pw + tx, (size_t)tile * sizeof(float));
        }
        rc = c->gpu ? clip_gpu_vision(c, px, nb, tile, tile, kind, feat, err)
                    : clip_cpu_vision(c, px, nb, tile, tile, kind, feat, err);
        for (int b = 0; b < nb && !rc; b++) {
            int gx0 = xs[(t0 + b) % nx] / p, gy0 = ys[(t0 + b) / nx] / p;
            for (int y = 0; y < tg; y++)
                for (int x = 0; x < tg; x++) {
                    int gx = gx0 + x, gy = gy0 + y;
                    if (gx >= sp->gw || gy >= sp->gh) continue;
                    float *f = feat + ((size_t)b * tg * tg + y * tg + x) * P;
                    clip_l2_normalize(f, P);
                    float *a = acc + ((size_t)gy * sp->gw + gx) * P;
                    for (int k = 0; k < P; k++) a[k] += f[k];
                    cnt[gy * sp->gw + gx] += 1;
                }
        }
    }
done:
    free(img);
    free(norm);
    free(px);
    free(feat);
    return rc;
}

void sp_clip_upsample(const float *grid, int gw, int gh, int dim, int width, int height, float *out)
{
    for (int y = 0; y < height; y++) {
        float fy = (y + 0.5f) * gh / height - 0.5f;
        int y0 = (int)floorf(fy);
        float ty = fy - y0;
        int ya = y0 < 0 ? 0 : y0 >= gh ? gh - 1 : y0, yb = y0 + 1 >= gh ? gh - 1 : y0 + 1 < 0 ? 0 : y0 + 1;
        for (int x = 0; x < width; x++) {
            float fx = (x + 0.5f) * gw / width - 0.5f;
            int x0 = (int)floorf(fx);
            float tx = fx - x0;
            int xa = x0 < 0 ? 0 : x0 >= gw ? gw - 1 : x0, xb = x0 + 1 >= gw ? gw - 1 : x0 + 1 < 0 ? 0 : x0 + 1;
            const float *a = grid + ((size_t)ya * gw + xa) * dim, *b = grid + ((size_t)ya * gw + xb) * dim;
            const float *cc = grid + ((size_t)yb * gw + xa) * dim, *d = grid + ((size_t)yb * gw + xb) * dim;
            float *o = out + ((size_t)y * width + x) * dim;
            float w00 = (1 - tx) * (1 - ty), w01 = tx * (1 - ty), w10 = (1 - tx) * ty, w11 = tx * ty;
            for (int k = 0; k < dim; k++) o[k] = w00 * a[k] + w01 * b[k] + w10 * cc[k] + w11 * d[k];
        }
    }
}

int sp_clip_dense_features(sp_clip *c, const float *rgb, int width, int height,
                           const sp_clip_dense_opts *o, float *out, sp_error *err)
{
    sp_clip_dense_opts d = o ? *o : sp_clip_dense_opts_default();
    if (d.n_scales < 1 || d.n_scales > 4)
        return sp_error_set(err, SP_E_ARG, "dense features: %d scales (1..4)", d.n_scales);
    for (int i = 0; i < d.n_scales; i++)
        if (!(d.scales[i] > 0.05f && d.scales[i] <= 8.f))
            return sp_error_set(err, SP_E_ARG, "dense features: scale %g outside (0.05, 8]", d.scales[i]);
    if (width < 1 || height < 1)
        return sp_error_set(err, SP_E_ARG, "dense features: image size %dx%d", width, height);
    if (d.batch < 1) d.batch = 1;
    int tile, stride, P = c->cfg.projection_dim;
    clip_tile_params(c, &d, &tile, &stride);
    clip_out_kind kind = d.head == SP_CLIP_HEAD_MASKCLIP ? CLIP_OUT_DENSE_MASKCLIP : CLIP_OUT_DENSE_CLEARCLIP;
    if (c->gpu) return clip_gpu_dense(c, rgb, width, height, &d, tile, stride, kind, out, err);
    clip_scale_plan base;
    clip_plan_scale(c, d.scales[0], tile, width, height, &base);
    memset(out, 0, (size_t)base.gw * base.gh * P * sizeof *out);
    int rc = 0;
    for (int s = 0; s < d.n_scales && !rc; s++) {
        clip_scale_plan sp;
        clip_plan_scale(c, d.scales[s], tile, width, height, &sp);
        float *acc = calloc((size_t)sp.gw * sp.gh * P, sizeof *acc);
        float *cnt = calloc((size_t)sp.gw * sp.gh, sizeof *cnt);
        float *up = s ? malloc((size_t)base.gw * base.gh * P * sizeof *up) : NULL;
        if (!acc || !cnt || (s && !up)) {
            rc = sp_error_set(err, SP_E_NOMEM, "dense features: out of memory");
        } else if (!(rc = dense_scale(c, rgb, width, height, &sp, tile, stride, kind, d.batch, acc,
                                      cnt, err))) {
            for (long i = 0; i < (long)sp.gw * sp.gh; i++) {
                float inv = cnt[i] > 0 ? 1.f / cnt[i] : 0.f;
                for (int k = 0; k < P; k++) acc[(size_t)i * P + k] *= inv;
            }
            /* the grids of all scales cover the image, so resampling maps cell centres */
            const float *src = acc;
            if (s) {
                sp_clip_upsample(acc, sp.gw, sp.gh, P, base.gw, base.gh, up);
                src = up;
            }
            for (size_t i = 0; i < (size_t)base.gw * base.gh * P; i++) out[i] += src[i];
        }
        free(acc);
        free(cnt);
        free(up);
    }
    for (long i = 0; i < (long)base.gw * base.gh && !rc; i++) clip_l2_normalize(out + (size_t)i * P, P);
    return rc;
}
