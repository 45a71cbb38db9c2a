/* Colour maps for rendered values: Turbo, and depth images mapped through it (previews, the CLI's
 * depth renders, heatmaps). */
#include <stdlib.h>

#include "render/turbo.h"
#include "semsplat/render.h"

void sp_turbo(float t, float rgb[3]) { sp_turbo_eval(t, rgb); }

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
