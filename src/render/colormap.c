/* Colour maps for rendered values: Turbo, and depth images mapped through it (previews, the CLI's
 * depth renders, heatmaps). */
#include <stdlib.h>

#include "semsplat/render.h"

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

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

int sp_depth_colormap(const float *depth, const float *alpha, size_t n, float *rgb, sp_error *err)
{
    float *vals = malloc((n ? n : 1) * sizeof(float));
    if (!vals) return sp_error_set(err, SP_E_NOMEM, "depth colour map: out of memory for %zu pixels", n);
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (alpha[i] >= 0.5f && depth[i] > 0.f) vals[m++] = depth[i];
    float lo = 0.f, hi = 1.f;
    if (m > 0) {
        qsort(vals, m, sizeof(float), cmp_float);
        lo = vals[(size_t)(0.02 * (double)(m - 1))];
        hi = vals[(size_t)(0.98 * (double)(m - 1))];
        if (!(hi > lo)) hi = lo + 1e-3f;
    }
    for (size_t i = 0; i < n; i++) {
        if (alpha[i] < 0.5f || !(depth[i] > 0.f)) {
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = 0.f;
            continue;
        }
        sp_turbo(1.f - (depth[i] - lo) / (hi - lo), rgb + 3 * i); /* near = red, far = blue */
    }
    free(vals);
    return 0;
}
