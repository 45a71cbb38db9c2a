/* Regular 2D/3D grids and exact Euclidean distance transforms (Felzenszwalb & Huttenlocher 2012),
 * shared by view selection, synth's planner and navigation's costmap. */
#include "semsplat/core.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Squared distance standing for "no seed on this line yet": far above any real squared cell
 * distance (grids are limited to 2^31 cells), small enough that sums stay finite in double. */
#define EDT_FAR 1e20

static int grid_cells(size_t *out, int nx, int ny, int nz, float res, const char *what,
                      sp_error *err)
{
    if (nx <= 0 || ny <= 0 || nz <= 0)
        return sp_error_set(err, SP_E_ARG, "%s: size %dx%dx%d must be positive", what, nx, ny, nz);
    if (!(res > 0) || !isfinite(res))
        return sp_error_set(err, SP_E_ARG, "%s: cell size %g must be positive", what, (double)res);
    size_t n = (size_t)nx * (size_t)ny;
    if (n / (size_t)ny != (size_t)nx || n > ((size_t)1 << 31) / (size_t)nz)
        return sp_error_set(err, SP_E_NOMEM, "%s: %dx%dx%d cells is too many", what, nx, ny, nz);
    *out = n * (size_t)nz;
    return SP_OK;
}

int sp_grid2_alloc(sp_grid2 *g, int nx, int ny, float res, float origin_x, float origin_y,
                   sp_error *err)
{
    memset(g, 0, sizeof *g);
    size_t n;
    int rc = grid_cells(&n, nx, ny, 1, res, "grid", err);
    if (rc) return rc;
    g->data = sp_calloc(n, sizeof(float));
    if (!g->data) return sp_error_set(err, SP_E_NOMEM, "grid: out of memory for %dx%d cells", nx, ny);
    g->nx = nx;
    g->ny = ny;
    g->res = res;
    g->origin[0] = origin_x;
    g->origin[1] = origin_y;
    return SP_OK;
}

int sp_grid3_alloc(sp_grid3 *g, int nx, int ny, int nz, float res, const float origin[3],
                   sp_error *err)
{
    memset(g, 0, sizeof *g);
    size_t n;
    int rc = grid_cells(&n, nx, ny, nz, res, "voxel grid", err);
    if (rc) return rc;
    g->data = sp_calloc(n, sizeof(float));
    if (!g->data)
        return sp_error_set(err, SP_E_NOMEM, "voxel grid: out of memory for %dx%dx%d cells", nx, ny, nz);
    g->nx = nx;
    g->ny = ny;
    g->nz = nz;
    g->res = res;
    memcpy(g->origin, origin, sizeof g->origin);
    return SP_OK;
}

void sp_grid2_free(sp_grid2 *g)
{
    if (!g) return;
    sp_free(g->data);
    memset(g, 0, sizeof *g);
}

void sp_grid3_free(sp_grid3 *g)
{
    if (!g) return;
    sp_free(g->data);
    memset(g, 0, sizeof *g);
}

static int axis_cell(float v, float origin, float res, int n, int *i)
{
    float f = floorf((v - origin) / res);
    /* clamp before the int conversion so far-away points cannot overflow it */
    if (!(f > -1e9f)) f = -1e9f;
    if (f > 1e9f) f = 1e9f;
    *i = (int)f;
    return *i >= 0 && *i < n;
}

int sp_grid2_cell(const sp_grid2 *g, float x, float y, int *ix, int *iy)
{
    int a = axis_cell(x, g->origin[0], g->res, g->nx, ix);
    int b = axis_cell(y, g->origin[1], g->res, g->ny, iy);
    return a && b;
}

int sp_grid3_cell(const sp_grid3 *g, const float p[3], int idx[3])
{
    int a = axis_cell(p[0], g->origin[0], g->res, g->nx, &idx[0]);
    int b = axis_cell(p[1], g->origin[1], g->res, g->ny, &idx[1]);
    int c = axis_cell(p[2], g->origin[2], g->res, g->nz, &idx[2]);
    return a && b && c;
}

void sp_grid2_center(const sp_grid2 *g, int ix, int iy, float *x, float *y)
{
    *x = g->origin[0] + ((float)ix + 0.5f) * g->res;
    *y = g->origin[1] + ((float)iy + 0.5f) * g->res;
}

void sp_grid3_center(const sp_grid3 *g, const int idx[3], float p[3])
{
    for (int a = 0; a < 3; a++) p[a] = g->origin[a] + ((float)idx[a] + 0.5f) * g->res;
}

/* ---- distance transform ----------------------------------------------------------------------- */

/* One line of the 1D transform d[q] = min_p (q - p)^2 + f[p] (F&H's lower envelope of
 * parabolas). f and d hold n values; v (int) and z (n + 1 doubles) are scratch. */
static void edt_line(const double *f, double *d, int n, int *v, double *z)
{
    int k = 0;
    v[0] = 0;
    z[0] = -INFINITY;
    z[1] = INFINITY;
    for (int q = 1; q < n; q++) {
        /* where parabola q rises above the envelope's last one; z[0] = -inf stops the pop */
        double s;
        for (;;) {
            int p = v[k];
            s = ((f[q] + (double)q * q) - (f[p] + (double)p * p)) / (2.0 * (q - p));
            if (s > z[k]) break;
            k--;
        }
        k++;
        v[k] = q;
        z[k] = s;
        z[k + 1] = INFINITY;
    }
    k = 0;
    for (int q = 0; q < n; q++) {
        while (z[k + 1] < q) k++;
        double dq = (double)(q - v[k]);
        d[q] = dq * dq + f[v[k]];
    }
}

/* A pass along one axis of a [n2][n1][n0] double volume, in place: lines are `len` values
 * `stride` apart; line i starts at base(i). */
typedef struct edt_pass {
    double *vol;
    int len;
    size_t stride;
    int n_inner;        /* lines are indexed i = outer * n_inner + inner */
    size_t outer_step, inner_step;
    double *scratch;    /* per thread: f, d (len each), z (len + 1) */
    int *vscratch;      /* per thread: v (len) */
} edt_pass;

static void edt_pass_line(void *ctx, long i, int tid)
{
    edt_pass *p = ctx;
    size_t base = (size_t)(i / p->n_inner) * p->outer_step + (size_t)(i % p->n_inner) * p->inner_step;
    double *f = p->scratch + (size_t)tid * (3 * (size_t)p->len + 1);
    double *d = f + p->len, *z = d + p->len;
    int *v = p->vscratch + (size_t)tid * (size_t)p->len;
    for (int q = 0; q < p->len; q++) f[q] = p->vol[base + (size_t)q * p->stride];
    edt_line(f, d, p->len, v, z);
    for (int q = 0; q < p->len; q++) p->vol[base + (size_t)q * p->stride] = d[q];
}

/* Runs the separable transform over dims[0..n_dims) (dims[0] fastest). */
static int edt_run(const uint8_t *seed, const int *dims, int n_dims, float res, float *out,
                   sp_pool *pool, const char *what, sp_error *err)
{
    size_t n;
    int rc = grid_cells(&n, dims[0], n_dims > 1 ? dims[1] : 1, n_dims > 2 ? dims[2] : 1, res, what, err);
    if (rc) return rc;
    if (!seed || !out) return sp_error_set(err, SP_E_ARG, "%s: NULL buffer", what);
    int maxlen = 0;
    for (int a = 0; a < n_dims; a++) maxlen = dims[a] > maxlen ? dims[a] : maxlen;
    int threads = sp_pool_size(pool);
    double *vol = sp_alloc(n * sizeof(double));
    double *scratch = sp_alloc((size_t)threads * (3 * (size_t)maxlen + 1) * sizeof(double));
    int *vscratch = sp_alloc((size_t)threads * (size_t)maxlen * sizeof(int));
    if (!vol || !scratch || !vscratch) {
        sp_free(vol);
        sp_free(scratch);
        sp_free(vscratch);
        return sp_error_set(err, SP_E_NOMEM, "%s: out of memory for %zu cells", what, n);
    }
    for (size_t i = 0; i < n; i++) vol[i] = seed[i] ? 0.0 : EDT_FAR;
    size_t stride = 1;
    for (int a = 0; a < n_dims; a++) {
        /* lines along axis a: the cells before it (inner) times the cells after it (outer) */
        size_t inner = stride, outer = n / (stride * (size_t)dims[a]);
        edt_pass p = {vol, dims[a], stride, (int)inner, stride * (size_t)dims[a], 1, scratch, vscratch};
        if (dims[a] > 1) sp_pool_for(pool, (long)(inner * outer), edt_pass_line, &p);
        stride *= (size_t)dims[a];
    }
    for (size_t i = 0; i < n; i++)
        out[i] = vol[i] >= 0.5 * EDT_FAR ? INFINITY : (float)(sqrt(vol[i]) * (double)res);
    sp_free(vol);
    sp_free(scratch);
    sp_free(vscratch);
    return SP_OK;
}

int sp_edt2(const uint8_t *seed, int nx, int ny, float res, float *out, sp_pool *pool,
            sp_error *err)
{
    int dims[2] = {nx, ny};
    return edt_run(seed, dims, 2, res, out, pool, "distance transform", err);
}

int sp_edt3(const uint8_t *seed, int nx, int ny, int nz, float res, float *out, sp_pool *pool,
            sp_error *err)
{
    int dims[3] = {nx, ny, nz};
    return edt_run(seed, dims, 3, res, out, pool, "3D distance transform", err);
}
