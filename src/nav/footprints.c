/* Occupancy evidence from the splat itself: opacity-weighted Gaussian footprints (their extent,
 * not their centres) per voxel of the robot's band, and the floor the splat reconstructed. The
 * footprint layer of the costmap (sp_costmap_opts.occupancy = SP_OCCUPANCY_FOOTPRINTS); the
 * training views' scans (carve.c) veto footprints they saw through. */
#include <math.h>
#include <stdlib.h>

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

/* A band Gaussian's footprint: its weight per slice, the inverse of its xy covariance and the
 * cells it can reach. */
typedef struct fp_item {
    float wv[NAV_MAX_SLICES];
    float m[2], ia, ib, ic;
    int x0, y0, x1, y1;
} fp_item;

/* Gaussian i's footprint into *it; 0 when it adds nothing to the band. */
static int footprint_of(const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o, const nav_slices *sl,
                        size_t i, fp_item *it)
{
    float C[9];
    float op = gauss_cov(s, i, C);
    if (op < o->min_opacity) return 0;
    const float *m = s->means + 3 * i;
    float sz = fmaxf(sqrtf(C[8]), 1e-6f);
    if (m[2] + 3.0f * sz < cm->band[0] || m[2] - 3.0f * sz > cm->band[1]) return 0;
    int any = 0;
    for (int v = 0; v < sl->n; v++) {
        float lo = sl->z0 + v * sl->dz, w = op * band_fraction(m[2], sz, lo, lo + sl->dz);
        it->wv[v] = w < MIN_SLICE_WEIGHT ? 0.0f : w;
        any |= it->wv[v] > 0.0f;
    }
    if (!any) return 0;
    /* a floor of 1e-8 m^2 keeps a needle's covariance invertible */
    float a = C[0] + 1e-8f, b = C[1], c = C[4] + 1e-8f, det = a * c - b * b;
    if (!(det > 0)) return 0;
    it->ia = c / det, it->ib = -b / det, it->ic = a / det;
    it->m[0] = m[0], it->m[1] = m[1];
    float rx = o->footprint_sigmas * sqrtf(a), ry = o->footprint_sigmas * sqrtf(c);
    sp_costmap_cell(cm, m[0] - rx, m[1] - ry, &it->x0, &it->y0);
    sp_costmap_cell(cm, m[0] + rx, m[1] + ry, &it->x1, &it->y1);
    if (it->x0 < 0) it->x0 = 0;
    if (it->y0 < 0) it->y0 = 0;
    if (it->x1 >= cm->nx) it->x1 = cm->nx - 1;
    if (it->y1 >= cm->ny) it->y1 = cm->ny - 1;
    return 1;
}

/* Adds the footprint's rows [ya, yb] to log_free. */
static void footprint_rows(const sp_costmap *cm, const sp_costmap_opts *o, const nav_slices *sl, const fp_item *it,
                           int ya, int yb, float *log_free)
{
    const float k2 = o->footprint_sigmas * o->footprint_sigmas;
    for (int iy = ya; iy <= yb; iy++)
        for (int ix = it->x0; ix <= it->x1; ix++) {
            float bx = cm->origin[0] + ix * cm->res, by = cm->origin[1] + iy * cm->res;
            float d2 = maha_box_min(it->ia, it->ib, it->ic, it->m, bx, by, bx + cm->res, by + cm->res);
            if (d2 > k2) continue;
            float g = expf(-0.5f * d2);
            long cell = nav_idx(cm, ix, iy);
            for (int v = 0; v < sl->n; v++)
                if (it->wv[v] > 0) log_free[v * sl->cells + cell] += log1pf(-fminf(it->wv[v] * g, 0.999f));
        }
}

/* The footprints are found in parallel over chunks of Gaussians (each chunk's into its own
 * stretch of items), then added in parallel over stripes of rows, every stripe walking all the
 * items in Gaussian order: each voxel sums its terms in the serial order, whatever the thread
 * count. */
#define FP_CHUNKS 64
#define FP_STRIPES 16
typedef struct fp_job {
    const sp_costmap *cm;
    const sp_splat *s;
    const sp_costmap_opts *o;
    const nav_slices *sl;
    fp_item *items;              /* [n] chunk k's from k * chunk */
    size_t chunk, count[FP_CHUNKS];
    long n_chunks;
    float *log_free;
} fp_job;

static void fp_find(void *ctx, long k, int thread_id)
{
    (void)thread_id;
    fp_job *j = ctx;
    size_t i0 = (size_t)k * j->chunk, i1 = i0 + j->chunk < j->s->n ? i0 + j->chunk : j->s->n, m = i0;
    for (size_t i = i0; i < i1; i++) m += footprint_of(j->cm, j->s, j->o, j->sl, i, &j->items[m]);
    j->count[k] = m - i0;
}

static void fp_stripe(void *ctx, long k, int thread_id)
{
    (void)thread_id;
    const fp_job *j = ctx;
    int rows = (j->cm->ny + FP_STRIPES - 1) / FP_STRIPES, ya = (int)k * rows, yb = ya + rows - 1;
    for (long c = 0; c < j->n_chunks; c++) {
        const fp_item *it = j->items + (size_t)c * j->chunk;
        for (size_t q = 0; q < j->count[c]; q++, it++) {
            int y0 = it->y0 > ya ? it->y0 : ya, y1 = it->y1 < yb ? it->y1 : yb;
            if (y0 <= y1) footprint_rows(j->cm, j->o, j->sl, it, y0, y1, j->log_free);
        }
    }
}

/* Accumulates log(1 - w) per voxel over the band Gaussians' footprints: w = opacity x (share of
 * the Gaussian's vertical mass inside the slice) x exp(-d^2 / 2), d the smallest Mahalanobis
 * distance (xy marginal) from the Gaussian's centre to any point of the cell: the most opaque
 * the Gaussian gets anywhere in the cell, so a cell counts when its footprint covers any part of
 * it, not only its centre, and never for being next to a surface. Out to footprint_sigmas.
 * Fused per slice, a wall's column of tens of Gaussians cannot add its tails up into a phantom
 * obstacle beside it; within a slice, neighbours' tails fill the gaps between them as they do in
 * the rendered image. */
int nav_footprints(sp_pool *pool, const sp_costmap *cm, const sp_splat *s, const sp_costmap_opts *o,
                   const nav_slices *sl, float *log_free)
{
    fp_job j = {cm, s, o, sl, malloc(sizeof(fp_item) * (s->n ? s->n : 1)), (s->n + FP_CHUNKS - 1) / FP_CHUNKS, {0}, 0,
                log_free};
    if (!j.items) return SP_E_NOMEM;
    j.n_chunks = j.chunk ? (long)((s->n + j.chunk - 1) / j.chunk) : 0;
    sp_pool_for(pool, j.n_chunks, fp_find, &j);
    sp_pool_for(pool, FP_STRIPES, fp_stripe, &j);
    free(j.items);
    return SP_OK;
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
