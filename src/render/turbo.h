/* The Turbo colour map (Mikhailov, Google AI 2019), the published polynomial approximation, as
 * one inline function for host and device code (nvcc: __host__ __device__), so sp_turbo and the
 * GPU heatmap colour a value identically. */
#ifndef SP_RENDER_TURBO_H
#define SP_RENDER_TURBO_H

#include "render/gauss_math.h" /* SP_HD */

static inline SP_HD void sp_turbo_eval(float t, float rgb[3])
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

#endif
