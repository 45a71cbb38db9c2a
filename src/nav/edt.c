/* Exact Euclidean distance transform of a 2D seed mask (Felzenszwalb & Huttenlocher, "Distance
 * Transforms of Sampled Functions", 2012): a 1-D lower envelope of parabolas along columns,
 * then rows. Used for the costmap's clearance and inflation. */
#include <stdlib.h>

#include "nav_internal.h"

#define EDT_INF 1e20f

/* f [n] squared distances in, d [n] out; v [n] ints and z [n+1] floats scratch. */
static void edt_1d(const float *f, int n, float *d, int *v, float *z)
{
    int k = 0;
    v[0] = 0;
    z[0] = -EDT_INF;
    z[1] = EDT_INF;
    for (int q = 1; q < n; q++) {
        if (f[q] >= EDT_INF) continue; /* no parabola from an empty sample */
        if (f[v[k]] >= EDT_INF) { /* the envelope so far holds only empty samples */
            v[k] = q;
            continue;
        }
        float s;
        for (;;) {
            int p = v[k];
            s = ((f[q] + (float)q * q) - (f[p] + (float)p * p)) / (2.0f * (float)(q - p));
            if (s <= z[k] && k > 0) k--;
            else break;
        }
        if (s <= z[k]) { /* k == 0: q dominates the only parabola */
            v[0] = q;
            continue;
        }
        k++;
        v[k] = q;
        z[k] = s;
        z[k + 1] = EDT_INF;
    }
    if (f[v[0]] >= EDT_INF) {
        for (int q = 0; q < n; q++) d[q] = EDT_INF;
        return;
    }
    k = 0;
    for (int q = 0; q < n; q++) {
        while (z[k + 1] < (float)q) k++;
        float dq = (float)(q - v[k]);
        d[q] = dq * dq + f[v[k]];
    }
}

int nav_edt2(const uint8_t *seed, int nx, int ny, float res, float *out, sp_error *err)
{
    if (nx <= 0 || ny <= 0) return sp_error_set(err, SP_E_ARG, "edt: grid %dx%d", nx, ny);
    int m = nx > ny ? nx : ny;
    float *f = malloc(sizeof(float) * m), *d = malloc(sizeof(float) * m);
    float *z = malloc(sizeof(float) * (m + 1));
    int *v = malloc(sizeof(int) * m);
    if (!f || !d || !z || !v) {
        free(f), free(d), free(z), free(v);
        return sp_error_set(err, SP_E_NOMEM, "edt: out of memory for a %dx%d grid", nx, ny);
    }
    for (int x = 0; x < nx; x++) {
        for (int y = 0; y < ny; y++) f[y] = seed[(long)y * nx + x] ? 0.0f : EDT_INF;
        edt_1d(f, ny, d, v, z);
        for (int y = 0; y < ny; y++) out[(long)y * nx + x] = d[y];
    }
    for (int y = 0; y < ny; y++) {
        float *row = out + (long)y * nx;
        for (int x = 0; x < nx; x++) f[x] = row[x];
        edt_1d(f, nx, d, v, z);
        for (int x = 0; x < nx; x++) row[x] = d[x] >= EDT_INF ? INFINITY : sqrtf(d[x]) * res;
    }
    free(f), free(d), free(z), free(v);
    return SP_OK;
}
