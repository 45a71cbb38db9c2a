/* Dense features of one image on the device: the image goes up once; the antialiased bicubic
 * resize (PIL's weights, made on the host), normalisation and padding, tile extraction, the
 * dense head over all tiles in as few forward passes as memory allows, per-patch L2
 * normalisation, overlap averaging (a gather in tile order, so the result is deterministic),
 * resampling of further scales onto the first scale's grid and the final normalisation all run
 * here; one grid comes back. Same steps and order as the CPU path in dense.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clip_gpu.cuh"

enum { D_RGB, D_TMP, D_NORM, D_PX, D_FEAT, D_GRID, D_OUT, D_TAB };

static int blocks(size_t n) { return (int)((n + 255) / 256 < 131072 ? (n + 255) / 256 : 131072); }

/* horizontal pass: tmp [h][rw][3] */
__global__ void k_resize_h(const float *in, int w, int h, float *tmp, int rw, const float *wx, const int *x0,
                           const int *cx, int taps)
{
    size_t total = (size_t)h * rw;
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        int y = (int)(i / rw), o = (int)(i % rw);
        const float *wi = wx + (size_t)o * taps, *src = in + ((size_t)y * w + x0[o]) * 3;
        float s0 = 0, s1 = 0, s2 = 0;
        for (int k = 0; k < cx[o]; k++) {
            s0 += wi[k] * src[3 * k];
            s1 += wi[k] * src[3 * k + 1];
            s2 += wi[k] * src[3 * k + 2];
        }
        float *t = tmp + i * 3;
        t[0] = s0;
        t[1] = s1;
        t[2] = s2;
    }
}

struct norm_args {
    float mean[3], std[3];
};

/* vertical pass + normalisation into the padded planar image norm [3][ph][pw] (padding 0, the
 * mean colour) */
__global__ void k_resize_v(const float *tmp, int rw, int rh, float *norm, int pw, int ph, const float *wy,
                           const int *y0, const int *cy, int taps, norm_args na)
{
    size_t total = (size_t)ph * pw, plane = total;
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        int y = (int)(i / pw), x = (int)(i % pw);
        float v[3] = {0, 0, 0};
        bool in = y < rh && x < rw;
        if (in) {
            const float *wi = wy + (size_t)y * taps;
            for (int k = 0; k < cy[y]; k++) {
                const float *src = tmp + ((size_t)(y0[y] + k) * rw + x) * 3;
                v[0] += wi[k] * src[0];
                v[1] += wi[k] * src[1];
                v[2] += wi[k] * src[2];
            }
        }
        for (int ch = 0; ch < 3; ch++) norm[ch * plane + i] = in ? (v[ch] - na.mean[ch]) / na.std[ch] : 0.f;
    }
}

/* tiles t0 .. t0+nb-1 (row-major over the tile grid) -> px [nb][3][tile][tile] */
__global__ void k_tiles(const float *norm, int pw, int ph, float *px, int t0, int nb, int tile, const int *xs,
                        const int *ys, int nx)
{
    size_t tt = (size_t)tile * tile, total = (size_t)nb * 3 * tt;
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        int x = (int)(i % tile), y = (int)((i / tile) % tile), ch = (int)((i / tt) % 3), b = (int)(i / (3 * tt));
        int t = t0 + b, tx = xs[t % nx], ty = ys[t / nx];
        px[i] = norm[((size_t)ch * ph + ty + y) * pw + tx + x];
    }
}

/* one warp per row: inverse L2 norm (0 for a zero row) */
__global__ void k_invnorm(const float *f, float *inv, int rows, int P)
{
    int r = (int)((blockIdx.x * blockDim.x + threadIdx.x) >> 5), lane = threadIdx.x & 31;
    if (r >= rows) return;
    const float *v = f + (size_t)r * P;
    float s = 0;
    for (int k = lane; k < P; k += 32) s += v[k] * v[k];
    for (int o = 16; o > 0; o >>= 1) s += __shfl_xor_sync(0xffffffffu, s, o);
    if (lane == 0) inv[r] = s > 0 ? rsqrtf(s) : 0.f;
}

/* one block per grid cell: the normalised features of every tile covering it, summed in tile
 * order, over the count */
__global__ void k_cells(const float *feat, const float *inv, float *grid, int gw, int P, int tg, int p,
                        const int *xs, const int *ys, int nx, int ny)
{
    int cell = blockIdx.x, gx = cell % gw, gy = cell / gw;
    for (int k = threadIdx.x; k < P; k += blockDim.x) {
        float s = 0;
        int cnt = 0;
        for (int iy = 0; iy < ny; iy++) {
            int ty = ys[iy] / p;
            if (gy < ty || gy >= ty + tg) continue;
            for (int ix = 0; ix < nx; ix++) {
                int tx = xs[ix] / p;
                if (gx < tx || gx >= tx + tg) continue;
                size_t row = ((size_t)iy * nx + ix) * tg * tg + (size_t)(gy - ty) * tg + (gx - tx);
                s += feat[row * P + k] * inv[row];
                cnt++;
            }
        }
        grid[(size_t)cell * P + k] = s * (cnt > 0 ? 1.f / cnt : 0.f);
    }
}

/* out [H][W][P] += bilinear(grid [gh][gw][P]) with cell centres at (i + 0.5) * W / gw
 * (sp_clip_upsample's arithmetic) */
__global__ void k_upsample_add(const float *grid, int gw, int gh, int P, float *out, int W, int H)
{
    size_t total = (size_t)W * H * P;
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        int k = (int)(i % P);
        size_t pix = i / P;
        int x = (int)(pix % W), y = (int)(pix / W);
        float fy = (y + 0.5f) * gh / H - 0.5f, fx = (x + 0.5f) * gw / W - 0.5f;
        int y0 = (int)floorf(fy), x0 = (int)floorf(fx);
        float ty = fy - y0, tx = fx - x0;
        int ya = y0 < 0 ? 0 : y0 >= gh ? gh - 1 : y0, yb = y0 + 1 >= gh ? gh - 1 : y0 + 1 < 0 ? 0 : y0 + 1;
        int xa = x0 < 0 ? 0 : x0 >= gw ? gw - 1 : x0, xb = x0 + 1 >= gw ? gw - 1 : x0 + 1 < 0 ? 0 : x0 + 1;
        float w00 = (1 - tx) * (1 - ty), w01 = tx * (1 - ty), w10 = (1 - tx) * ty, w11 = tx * ty;
        float v = w00 * grid[((size_t)ya * gw + xa) * P + k] + w01 * grid[((size_t)ya * gw + xb) * P + k] +
                  w10 * grid[((size_t)yb * gw + xa) * P + k] + w11 * grid[((size_t)yb * gw + xb) * P + k];
        out[i] += v;
    }
}

__global__ void k_l2_rows(float *x, int rows, int P)
{
    int r = (int)((blockIdx.x * blockDim.x + threadIdx.x) >> 5), lane = threadIdx.x & 31;
    if (r >= rows) return;
    float *v = x + (size_t)r * P, s = 0;
    for (int k = lane; k < P; k += 32) s += v[k] * v[k];
    for (int o = 16; o > 0; o >>= 1) s += __shfl_xor_sync(0xffffffffu, s, o);
    float inv = s > 0 ? rsqrtf(s) : 0.f;
    for (int k = lane; k < P; k += 32) v[k] *= inv;
}

/* ---- host -------------------------------------------------------------------------------------------- */

/* One scale's plan and its tables in 4-byte words: wx, x0, cx, wy, y0, cy, xs, ys. */
struct scale_job {
    clip_scale_plan sp;
    int nx, ny, tx, ty;      /* tiles across / down; taps per axis */
    size_t o_x0, o_cx, o_wy, o_y0, o_cy, o_xs, o_ys, words;
    uint32_t *tab;
};

static int job_make(sp_clip *c, scale_job *j, float s, int tile, int stride, int width, int height)
{
    memset(j, 0, sizeof *j);
    clip_plan_scale(c, s, tile, width, height, &j->sp);
    j->nx = clip_tile_starts(j->sp.pw, tile, stride, NULL, 0);
    j->ny = clip_tile_starts(j->sp.ph, tile, stride, NULL, 0);
    clip_axis_weights ax, ay;
    if (clip_axis_weights_make(&ax, width, j->sp.rw)) return -1;
    if (clip_axis_weights_make(&ay, height, j->sp.rh)) {
        clip_axis_weights_free(&ax);
        return -1;
    }
    int rw = j->sp.rw, rh = j->sp.rh;
    j->tx = ax.taps;
    j->ty = ay.taps;
    j->o_x0 = (size_t)rw * ax.taps;
    j->o_cx = j->o_x0 + rw;
    j->o_wy = j->o_cx + rw;
    j->o_y0 = j->o_wy + (size_t)rh * ay.taps;
    j->o_cy = j->o_y0 + rh;
    j->o_xs = j->o_cy + rh;
    j->o_ys = j->o_xs + j->nx;
    j->words = j->o_ys + j->ny;
    j->tab = (uint32_t *)malloc(j->words * 4);
    int rc = j->tab ? 0 : -1;
    if (!rc) {
        float *f = (float *)j->tab;
        int32_t *n = (int32_t *)j->tab;
        for (size_t i = 0; i < (size_t)rw * ax.taps; i++) f[i] = (float)ax.w[i];
        for (size_t i = 0; i < (size_t)rh * ay.taps; i++) f[j->o_wy + i] = (float)ay.w[i];
        for (int i = 0; i < rw; i++) {
            n[j->o_x0 + i] = ax.x0[i];
            n[j->o_cx + i] = ax.cnt[i];
        }
        for (int i = 0; i < rh; i++) {
            n[j->o_y0 + i] = ay.x0[i];
            n[j->o_cy + i] = ay.cnt[i];
        }
        clip_tile_starts(j->sp.pw, tile, stride, n + j->o_xs, j->nx);
        clip_tile_starts(j->sp.ph, tile, stride, n + j->o_ys, j->ny);
    }
    clip_axis_weights_free(&ax);
    clip_axis_weights_free(&ay);
    return rc;
}

static size_t max_sz(size_t a, size_t b) { return a > b ? a : b; }

/* One scale: resize + normalise, the dense head over the tiles, overlap averaging into grid. */
static int run_scale(sp_clip *c, const scale_job *j, int width, int height, int tile, int chunk,
                     clip_out_kind kind, float *grid, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    cudaStream_t st = g->stream;
    int p = c->cfg.patch_size, P = c->cfg.projection_dim, tg = tile / p, rc;
    const clip_scale_plan *sp = &j->sp;
    uint32_t *tab = (uint32_t *)g->dense[D_TAB].ptr;
    const float *ft = (const float *)tab;
    const int *it = (const int *)tab;
    CK(cudaMemcpyAsync(tab, j->tab, j->words * 4, cudaMemcpyHostToDevice, st), "dense tables");
    float *tmp = (float *)g->dense[D_TMP].ptr, *norm = (float *)g->dense[D_NORM].ptr;
    k_resize_h<<<blocks((size_t)height * sp->rw), 256, 0, st>>>((const float *)g->dense[D_RGB].ptr, width, height, tmp,
                                                               sp->rw, ft, it + j->o_x0, it + j->o_cx, j->tx);
    norm_args na;
    for (int ch = 0; ch < 3; ch++) {
        na.mean[ch] = c->cfg.image_mean[ch];
        na.std[ch] = c->cfg.image_std[ch];
    }
    k_resize_v<<<blocks((size_t)sp->ph * sp->pw), 256, 0, st>>>(tmp, sp->rw, sp->rh, norm, sp->pw, sp->ph, ft + j->o_wy,
                                                               it + j->o_y0, it + j->o_cy, j->ty, na);
    int n_tiles = j->nx * j->ny;
    size_t rows = (size_t)n_tiles * tg * tg;
    float *feat = (float *)g->dense[D_FEAT].ptr, *inv = feat + rows * P, *px = (float *)g->dense[D_PX].ptr;
    for (int t0 = 0; t0 < n_tiles; t0 += chunk) {
        int nb = n_tiles - t0 < chunk ? n_tiles - t0 : chunk;
        k_tiles<<<blocks((size_t)nb * 3 * tile * tile), 256, 0, st>>>(norm, sp->pw, sp->ph, px, t0, nb, tile,
                                                                      it + j->o_xs, it + j->o_ys, j->nx);
        if ((rc = clip_vision_device(c, px, 0, nb, tile, tile, kind, feat + (size_t)t0 * tg * tg * P, err))) return rc;
    }
    k_invnorm<<<(int)((rows + 7) / 8), 256, 0, st>>>(feat, inv, (int)rows, P);
    k_cells<<<sp->gw * sp->gh, 128, 0, st>>>(feat, inv, grid, sp->gw, P, tg, p, it + j->o_xs, it + j->o_ys, j->nx, j->ny);
    CK(cudaGetLastError(), "dense kernels");
    return 0;
}

extern "C" int clip_gpu_dense(sp_clip *c, const float *rgb, int width, int height, const sp_clip_dense_opts *o,
                              int tile, int stride, clip_out_kind kind, float *out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    int P = c->cfg.projection_dim, tg = tile / c->cfg.patch_size, ns = o->n_scales, rc = 0;
    /* every tile of the image in one forward pass when it fits: the GEMMs want the rows */
    int chunk = o->batch > 128 ? o->batch : 128;
    scale_job jobs[4];
    memset(jobs, 0, sizeof jobs);
    size_t need[8] = {(size_t)width * height * 3 * 4, 0, 0, 0, 0, 0, 0, 0};
    for (int s = 0; s < ns && !rc; s++) {
        scale_job *j = &jobs[s];
        if (job_make(c, j, o->scales[s], tile, stride, width, height)) {
            rc = sp_error_set(err, SP_E_NOMEM, "dense features: out of memory");
            break;
        }
        if (j->nx > CLIP_TILES_MAX || j->ny > CLIP_TILES_MAX) {
            rc = sp_error_set(err, SP_E_ARG, "dense features: %d x %d tiles (at most %d a side)", j->nx, j->ny,
                              CLIP_TILES_MAX);
            break;
        }
        size_t n_tiles = (size_t)j->nx * j->ny, nb = n_tiles < (size_t)chunk ? n_tiles : (size_t)chunk;
        need[D_TMP] = max_sz(need[D_TMP], (size_t)height * j->sp.rw * 3 * 4);
        need[D_NORM] = max_sz(need[D_NORM], (size_t)3 * j->sp.pw * j->sp.ph * 4);
        need[D_PX] = max_sz(need[D_PX], nb * 3 * tile * tile * 4);
        need[D_FEAT] = max_sz(need[D_FEAT], n_tiles * tg * tg * (P + 1) * 4);
        need[D_GRID] = max_sz(need[D_GRID], (size_t)j->sp.gw * j->sp.gh * P * 4);
        need[D_TAB] = max_sz(need[D_TAB], j->words * 4);
    }
    const clip_scale_plan *base = &jobs[0].sp;
    size_t cells = (size_t)base->gw * base->gh;
    need[D_OUT] = cells * P * 4;
    for (int i = 0; i < 8 && !rc; i++) rc = sp_device_scratch_reserve(g->dev, &g->dense[i], need[i] ? need[i] : 4, err);
    if (!rc) rc = clip_upload(c, g->dense[D_RGB].ptr, rgb, need[D_RGB], err);
    float *d_out = (float *)g->dense[D_OUT].ptr;
    for (int s = 0; s < ns && !rc; s++) {
        /* the first scale's grid is the output grid; later ones are resampled onto it */
        float *grid = s ? (float *)g->dense[D_GRID].ptr : d_out;
        if ((rc = run_scale(c, &jobs[s], width, height, tile, chunk, kind, grid, err))) break;
        if (s)
            k_upsample_add<<<blocks(cells * P), 256, 0, g->stream>>>(grid, jobs[s].sp.gw, jobs[s].sp.gh, P, d_out,
                                                                     base->gw, base->gh);
    }
    if (!rc) {
        k_l2_rows<<<(int)((cells + 7) / 8), 256, 0, g->stream>>>(d_out, (int)cells, P);
        if (cudaMemcpyAsync(out, d_out, cells * P * sizeof(float), cudaMemcpyDeviceToHost, g->stream) != cudaSuccess ||
            cudaStreamSynchronize(g->stream) != cudaSuccess)
            rc = sp_error_set(err, SP_E_DEVICE, "dense features on the GPU: %s", cudaGetErrorString(cudaGetLastError()));
    }
    for (int s = 0; s < ns; s++) free(jobs[s].tab);
    return rc;
}
