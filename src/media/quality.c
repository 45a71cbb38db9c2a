/* How useful a rendered preview is, from the picture alone: how much of it the splat covers and
 * how sharp the covered part is. Sharpness is the no-reference blur metric of Crete, Dolmiere,
 * Ladret and Nicolas ("The blur effect: perception and estimation with a new no-reference
 * perceptual blur metric", SPIE 2007): re-blurring a sharp picture removes much of the difference
 * between neighbouring pixels, re-blurring a blurry one removes little. */
#include <stdlib.h>

#include "semsplat/media.h"

#define REBLUR_TAPS 9 /* the paper's 1x9 average filter */

static double luma(const float *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

/* Blur along one axis (dx, dy) over pixels whose pair is covered; sums of the original
 * differences and of what the re-blur removed. */
static void blur_axis(const double *Y, const uint8_t *cov, int w, int h, int dx, int dy,
                      double *sum_d, double *sum_v)
{
    int half = REBLUR_TAPS / 2;
    for (int y = dy; y < h; y++)
        for (int x = dx; x < w; x++) {
            size_t i = (size_t)y * w + x, j = (size_t)(y - dy) * w + (x - dx);
            if (!cov[i] || !cov[j]) continue;
            double b0 = 0, b1 = 0;
            for (int k = -half; k <= half; k++) {
                int xi = x + k * dx, yi = y + k * dy, xj = xi - dx, yj = yi - dy;
                xi = xi < 0 ? 0 : xi >= w ? w - 1 : xi;
                yi = yi < 0 ? 0 : yi >= h ? h - 1 : yi;
                xj = xj < 0 ? 0 : xj >= w ? w - 1 : xj;
                yj = yj < 0 ? 0 : yj >= h ? h - 1 : yj;
                b0 += Y[(size_t)yi * w + xi];
                b1 += Y[(size_t)yj * w + xj];
            }
            double d = fabs(Y[i] - Y[j]), db = fabs(b0 - b1) / REBLUR_TAPS;
            *sum_d += d;
            *sum_v += fmax(0, d - db);
        }
}

int sp_media_view_quality(const float *rgb, const float *alpha, int w, int h, sp_view_quality *q,
                          sp_error *err)
{
    if (!rgb || w < 16 || h < 16)
        return sp_error_set(err, SP_E_ARG, "view quality: a %dx%d view%s: expected at least 16x16",
                            w, h, rgb ? "" : " without pixels");
    size_t n = (size_t)w * h;
    double *Y = malloc(n * sizeof *Y);
    uint8_t *cov = malloc(n);
    if (!Y || !cov) {
        free(Y);
        free(cov);
        return sp_error_set(err, SP_E_NOMEM, "view quality: out of memory");
    }
    size_t covered = 0;
    for (size_t i = 0; i < n; i++) {
        const float *p = rgb + 3 * i;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || (alpha && !isfinite(alpha[i]))) {
            free(Y);
            free(cov);
            return sp_error_set(err, SP_E_NUMERIC, "view quality: pixel %zu (x %zu, y %zu) is not finite",
                                i, i % (size_t)w, i / (size_t)w);
        }
        Y[i] = luma(p);
        cov[i] = !alpha || alpha[i] >= 0.5f;
        covered += cov[i];
    }
    double dh = 0, vh = 0, dv = 0, vv = 0;
    blur_axis(Y, cov, w, h, 1, 0, &dh, &vh);
    blur_axis(Y, cov, w, h, 0, 1, &dv, &vv);
    free(Y);
    free(cov);
    double bh = dh > 0 ? (dh - vh) / dh : 1, bv = dv > 0 ? (dv - vv) / dv : 1;
    q->coverage = (double)covered / n;
    q->blur = fmax(bh, bv);
    double s = (SP_BLUR_BLURRY - q->blur) / (SP_BLUR_BLURRY - SP_BLUR_SHARP);
    q->sharpness = s < 0 ? 0 : s > 1 ? 1 : s;
    q->score = 1 + 4 * q->coverage * q->sharpness;
    q->grade = (int)lround(q->score);
    return 0;
}
