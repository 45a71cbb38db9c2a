/* Ground-truth floor plans from a world's geometry: every triangle clipped to a height band and
 * rasterized conservatively into a 2D grid (a cell is occupied when the clipped triangle's xy
 * projection overlaps its interior). What navigation's costmap is measured against. */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

#define MAX_POLY 9
#define EDGE_SHRINK 1e-3f /* fraction of a cell: touching a cell's border is not overlapping it */

typedef struct plan_grid {
    float x0, y0, res;
    int nx, ny;
    uint8_t *occ;
} plan_grid;

/* Clips polygon (x, y, z) against z >= lo (sign 1) or z <= hi (sign -1) at plane. */
static int clip_z(const float (*in)[3], int n, float plane, int sign, float (*out)[3])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const float *a = in[i], *b = in[(i + 1) % n];
        float da = sign * (a[2] - plane), db = sign * (b[2] - plane);
        if (da >= 0) memcpy(out[m++], a, sizeof(float) * 3);
        if ((da >= 0) != (db >= 0)) {
            float t = da / (da - db);
            for (int k = 0; k < 3; k++) out[m][k] = a[k] + t * (b[k] - a[k]);
            m++;
        }
    }
    return m;
}

/* The cells of the grid that the box [lx, hx] x [ly, hy] touches. */
static void cell_range(const plan_grid *g, float lx, float ly, float hx, float hy, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = (int)floorf((lx - g->x0) / g->res), *x1 = (int)floorf((hx - g->x0) / g->res);
    *y0 = (int)floorf((ly - g->y0) / g->res), *y1 = (int)floorf((hy - g->y0) / g->res);
    if (*x0 < 0) *x0 = 0;
    if (*y0 < 0) *y0 = 0;
    if (*x1 >= g->nx) *x1 = g->nx - 1;
    if (*y1 >= g->ny) *y1 = g->ny - 1;
}

/* Marks the cells whose slightly shrunk interior the segment a-b crosses. */
static void mark_segment(plan_grid *g, const float *a, const float *b)
{
    int x0, y0, x1, y1;
    cell_range(g, fminf(a[0], b[0]), fminf(a[1], b[1]), fmaxf(a[0], b[0]), fmaxf(a[1], b[1]), &x0, &y0, &x1, &y1);
    float e = EDGE_SHRINK * g->res;
    for (int iy = y0; iy <= y1; iy++)
        for (int ix = x0; ix <= x1; ix++) {
            /* Liang-Barsky clip of the segment against the shrunk cell */
            float bx0 = g->x0 + ix * g->res + e, bx1 = g->x0 + (ix + 1) * g->res - e;
            float by0 = g->y0 + iy * g->res + e, by1 = g->y0 + (iy + 1) * g->res - e;
            float t0 = 0, t1 = 1, d[2] = {b[0] - a[0], b[1] - a[1]};
            float lo[2] = {bx0, by0}, hi[2] = {bx1, by1};
            int hit = 1;
            for (int k = 0; k < 2 && hit; k++) {
                if (fabsf(d[k]) < 1e-12f) {
                    if (a[k] < lo[k] || a[k] > hi[k]) hit = 0;
                    continue;
                }
                float ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
                if (ta > tb) {
                    float t = ta;
                    ta = tb, tb = t;
                }
                t0 = fmaxf(t0, ta), t1 = fminf(t1, tb);
                if (t0 > t1) hit = 0;
            }
            if (hit) g->occ[(size_t)iy * g->nx + ix] = 1;
        }
}

/* Marks cells whose centre lies inside the (convex) polygon. */
static void mark_interior(plan_grid *g, const float (*p)[3], int n)
{
    double area = 0;
    for (int i = 0; i < n; i++) {
        const float *a = p[i], *b = p[(i + 1) % n];
        area += (double)a[0] * b[1] - (double)b[0] * a[1];
    }
    if (fabs(area) < 1e-9) return; /* a vertical face projects to a line: its edges cover it */
    float lx = INFINITY, hx = -INFINITY, ly = INFINITY, hy = -INFINITY;
    for (int i = 0; i < n; i++) {
        lx = fminf(lx, p[i][0]), hx = fmaxf(hx, p[i][0]);
        ly = fminf(ly, p[i][1]), hy = fmaxf(hy, p[i][1]);
    }
    int x0, y0, x1, y1;
    cell_range(g, lx, ly, hx, hy, &x0, &y0, &x1, &y1);
    for (int iy = y0; iy <= y1; iy++)
        for (int ix = x0; ix <= x1; ix++) {
            float cx = g->x0 + (ix + 0.5f) * g->res, cy = g->y0 + (iy + 0.5f) * g->res;
            int pos = 0, neg = 0;
            for (int i = 0; i < n; i++) {
                const float *a = p[i], *b = p[(i + 1) % n];
                float c = (b[0] - a[0]) * (cy - a[1]) - (b[1] - a[1]) * (cx - a[0]);
                pos |= c > 0, neg |= c < 0;
            }
            if (!(pos && neg)) g->occ[(size_t)iy * g->nx + ix] = 1;
        }
}

int sp_synth_floor_plan(const sp_world *w, float z_lo, float z_hi, float res, const float origin[2],
                        int nx, int ny, uint8_t *occ, sp_error *err)
{
    if (!(res > 0) || nx < 1 || ny < 1 || !(z_hi > z_lo))
        return sp_error_set(err, SP_E_ARG, "floor plan: %dx%d cells of %g m, band %g..%g m", nx, ny,
                            res, z_lo, z_hi);
    plan_grid g = {origin[0], origin[1], res, nx, ny, occ};
    memset(occ, 0, (size_t)nx * ny);
    for (size_t t = 0; t < w->n_triangles; t++) {
        float tri[3][3], a[MAX_POLY][3], b[MAX_POLY][3];
        for (int i = 0; i < 3; i++) memcpy(tri[i], &w->positions[w->tris[3 * t + i] * 3], sizeof(float) * 3);
        int n = clip_z((const float(*)[3])tri, 3, z_lo, 1, a);
        if (n < 3) continue;
        n = clip_z((const float(*)[3])a, n, z_hi, -1, b);
        if (n < 3) continue;
        for (int i = 0; i < n; i++) mark_segment(&g, b[i], b[(i + 1) % n]);
        mark_interior(&g, (const float(*)[3])b, n);
    }
    return SP_OK;
}
