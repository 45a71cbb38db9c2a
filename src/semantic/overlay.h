/* One heatmap pixel and the display scale, as inline functions for host and device code (nvcc:
 * __host__ __device__): heatmap.c's sp_heatmap_overlay and the GPU heatmap (cuda/stages.cu) run
 * the same arithmetic. */
#ifndef SP_SEM_OVERLAY_H
#define SP_SEM_OVERLAY_H

#include <math.h>
#include <stdint.h>

#include "render/turbo.h"

static inline SP_HD uint8_t sem_to_u8(float v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return (uint8_t)lrintf(v * 255.0f);
}

/* A dimmed, desaturated scene keeps the context readable; the colour map fades in with
 * relevancy above neutral (0.5), so weak relevancy stays close to the base. c: rgb [3]. */
static inline SP_HD void sem_overlay_pixel(const float *c, float relevancy, uint8_t *o)
{
    float g = 0.55f * (0.3f * c[0] + 0.59f * c[1] + 0.11f * c[2]);
    float t = (relevancy - 0.5f) * 2.0f;
    t = t > 0 ? (t < 1 ? t : 1) : 0;
    float h[3];
    sp_turbo_eval(t, h);
    float a = 0.85f * (t * 1.5f < 1 ? t * 1.5f : 1);
    for (int k = 0; k < 3; k++) o[k] = sem_to_u8((1 - a) * (0.5f * g + 0.25f * c[k]) + a * h[k]);
}

/* Found: stretch the visible relevancy (largest rmax, at least 0.5) to the full colour range,
 * so a weak-but-real CLIP match still reads. */
static inline SP_HD float sem_found_scale(float rmax)
{
    return rmax > 0.55f ? 0.5f / (rmax - 0.5f) : 1.0f;
}

#endif
