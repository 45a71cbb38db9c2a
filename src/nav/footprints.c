/* Occupancy evidence from the splat itself: opacity-weighted Gaussian footprints (their extent,
 * not their centres) per voxel of the robot's band, and the floor the splat reconstructed. The
 * footprint layer of the costmap (sp_costmap_opts.occupancy = SP_OCCUPANCY_FOOTPRINTS); the
 * training views' scans (carve.c) veto footprints they saw through. */
#include <math.h>

#include "nav_internal.h"

#define MIN_SLICE_WEIGHT 0.02f /* a Gaussian's weight in a slice below this is left out */

/* World covariance of Gaussian i (row-major 3x3) and its opacity. */
static float gauss_cov(const sp_splat *s, size_t i, float C[9])
{
    float R[9], sc[3];
    sp_quat_to_mat3(s->quats + 4 * i, R);
    for (int k = 0; k < 3; k++) sc[k] = expf(2.0f * s->log_scales[3 * i + k]);
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            C[a * 3 + b] = R[a * 3] * R[b * 3] * sc[0] + R[a * 3 + 1] * R[b * 3 + 1] * sc[1] +
                           R[a * 3 + 2] * R[b * 3 + 2] * sc[2];
    return sp_sigmoid(s->opacity_logits[i]);
}

/* Share of a 1-D Gaussian (mean m, std sd) inside [lo, hi]. */
static float band_fraction(float m, float sd, float lo, float hi)
{
    float k = 1.0f / (sd * 1.41421356f);
    return 0.5f * (erff((hi - m) * k) - erff((lo - m) * k));
}

/* Smallest (q - m)^T A (q - m) over q in the box [x0, x1] x [y0, y1], A = [a b; b c] positive
 * definite: 0 when m is inside, else the least over the four edges (a 1-D quadratic each). */
static float maha_box_min(float a, float b, float c, const float m[2], float x0, float y0, float x1, float y1)
{
    if (m[0] >= x0 && m[0] <= x1 && m[1] >= y0 && m[1] <= y1) return 0.0f;
    const float ex[4][4] = {{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x1, y1, x0, y1}, {x0, y1, x0, y0}};
    float best = INFINITY;
    for (int k = 0; k < 4; k++) {
        float px = ex[k][0] - m[0], py = ex[k][1] - m[1], dx = ex[k][2] - ex[k][0], dy = ex[k][3] - ex[k][1];
        float ee = a * dx * dx + 2 * b * dx * dy + c * dy * dy, pe = a * px * dx + b * (px * dy + py * dx) + c * py * dy;
        float t = ee > 0 ? -pe / ee : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        float qx = px + t * dx, qy = py + t * dy, v = a * qx * qx + 2 * b * qx * qy + c * qy * qy;
        if (v < best) best = v;
    }
    return best;
}

/* Accumulates log(1 - w) per voxel over the band Gaussians' footprints: w = opacity x (share of
 * the Gaussian's vertical mass inside the slice) x exp(-d^2 / 2), d the smallest Mahalanobis
 * distance (xy marginal) from the Gaussian's centre to any point of the cell: the most opaque
 * the Gaussian gets anywhere in the cell, so a cell counts when its footprint covers any part of
 * it, not only its centre, and never for being next to a surface. Out to footprint_sigmas.
 * Fused per slice, a wall's column of tens of Gaussians cannot add its tails up into a phantom
 * obstacle beside it; within a slice, neighbours' tails fill the gaps between them as they do in
 * the rendered image. */
void nav_footprints(const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o, const nav_slices *sl,
                    float *log_free)
{
    const float k2 = o->footprint_sigmas * o->footprint_sigmas;
    float wv[NAV_MAX_SLICES];
    for (size_t i = 0; i < s->n; i++) {
        float C[9];
        float op = gauss_cov(s, i, C);
        if (op < o->min_opacity) continue;
        const float *m = s->means + 3 * i;
        float sz = fmaxf(sqrtf(C[8]), 1e-6f);
        if (m[2] + 3.0f * sz < cm->band[0] || m[2] - 3.0f * sz > cm->band[1]) continue;
        int any = 0;
        for (int v = 0; v < sl->n; v++) {
            float lo = sl->z0 + v * sl->dz, w = op * band_fraction(m[2], sz, lo, lo + sl->dz);
            wv[v] = w < MIN_SLICE_WEIGHT ? 0.0f : w;
            any |= wv[v] > 0.0f;
        }
        if (!any) continue;
        /* a floor of 1e-8 m^2 keeps a needle's covariance invertible */
        float a = C[0] + 1e-8f, b = C[1], c = C[4] + 1e-8f, det = a * c - b * b;
        if (!(det > 0)) continue;
        float ia = c / det, ib = -b / det, ic = a / det;
        float rx = o->footprint_sigmas * sqrtf(a), ry = o->footprint_sigmas * sqrtf(c);
        int x0, y0, x1, y1;
        sp_costmap_cell(cm, m[0] - rx, m[1] - ry, &x0, &y0);
        sp_costmap_cell(cm, m[0] + rx, m[1] + ry, &x1, &y1);
        if (x0 < 0) x0 = 0;
        if (y0 < 0) y0 = 0;
        if (x1 >= cm->nx) x1 = cm->nx - 1;
        if (y1 >= cm->ny) y1 = cm->ny - 1;
        for (int iy = y0; iy <= y1; iy++)
            for (int ix = x0; ix <= x1; ix++) {
                float bx = cm->origin[0] + ix * cm->res, by = cm->origin[1] + iy * cm->res;
                float d2 = maha_box_min(ia, ib, ic, m, bx, by, bx + cm->res, by + cm->res);
                if (d2 > k2) continue;
                float g = expf(-0.5f * d2);
                long cell = nav_idx(cm, ix, iy);
                for (int v = 0; v < sl->n; v++)
                    if (wv[v] > 0) log_free[v * sl->cells + cell] += log1pf(-fminf(wv[v] * g, 0.999f));
            }
    }
}

/* Floor the splat reconstructed: opaque Gaussians at the floor's height that are thin vertically
 * (sigma_z within half the floor tolerance) mark the cells of their footprint (1.5 sigma) as
 * floor seen: a camera saw the floor there, past whatever stands around it. Denser than the
 * rays' floor hits, whose rendered depth spreads a slanted floor over several centimetres. */
void nav_mark_floor(const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o, uint16_t *floor_seen)
{
    for (size_t i = 0; i < s->n; i++) {
        const float *m = s->means + 3 * i;
        if (fabsf(m[2] - cm->floor_z) > o->floor_tolerance_m) continue;
        float C[9];
        if (gauss_cov(s, i, C) < NAV_FLOOR_MIN_OPACITY || sqrtf(C[8]) > 0.5f * o->floor_tolerance_m) continue;
        float a = 2.25f * C[0], b = 2.25f * C[1], c = 2.25f * C[4], det = a * c - b * b;
        if (!(det > 0)) continue;
        float ia = c / det, ib = -b / det, ic = a / det, rx = sqrtf(a), ry = sqrtf(c);
        int x0, y0, x1, y1;
        sp_costmap_cell(cm, m[0] - rx, m[1] - ry, &x0, &y0);
        sp_costmap_cell(cm, m[0] + rx, m[1] + ry, &x1, &y1);
        for (int iy = y0 < 0 ? 0 : y0; iy <= y1 && iy < cm->ny; iy++)
            for (int ix = x0 < 0 ? 0 : x0; ix <= x1 && ix < cm->nx; ix++) {
                float p[2];
                sp_costmap_cell_center(cm, ix, iy, p);
                float dx = p[0] - m[0], dy = p[1] - m[1];
                if (ia * dx * dx + 2 * ib * dx * dy + ic * dy * dy > 1.0f) continue;
                uint16_t *f = &floor_seen[nav_idx(cm, ix, iy)];
                if (*f < UINT16_MAX) (*f)++;
            }
    }
}
