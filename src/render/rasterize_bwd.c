/* CPU backward compositing: one tile per pool item, walking the tile's list back to front from
 * the last contributor of any of its pixels. Per pixel it rebuilds the transmittance before each
 * Gaussian (T_i = T_{i+1} / (1 - alpha_i)) and keeps S = sum of the channels composited behind
 * it (starting from T_final * background), which gives
 *   dC/dc_i = alpha_i T_i,  dC/dalpha_i = T_i c_i - S / (1 - alpha_i),
 *   d(sum w)/dalpha_i = T_final / (1 - alpha_i),  and the same for depth with z_i.
 * Each (Gaussian, tile) pair writes its gradient sums to its own slot, never shared, so the
 * result does not depend on which thread ran which tile; project.c sums the slots per Gaussian
 * in slot order. */
#include <string.h>

#include "render/gauss_math.h"
#include "render/render_internal.h"

#define TILE_PIX (SP_TILE_SIZE * SP_TILE_SIZE)

typedef struct {
    cpu_raster *r;
    const sp_raster_grad_in *gin;
} bwd_ctx;

static inline __attribute__((always_inline)) void tile_backward(cpu_raster *r,
                                                                const sp_raster_grad_in *gin,
                                                                long tile, float *scratch, const int D)
{
    const int W = r->W, H = r->H;
    const int tx0 = (int)(tile % r->tiles_x) * SP_TILE_SIZE, ty0 = (int)(tile / r->tiles_x) * SP_TILE_SIZE;
    const int tx1 = tx0 + SP_TILE_SIZE - 1 < W - 1 ? tx0 + SP_TILE_SIZE - 1 : W - 1;
    const int ty1 = ty0 + SP_TILE_SIZE - 1 < H - 1 ? ty0 + SP_TILE_SIZE - 1 : H - 1;
    const int stride = SP_SLOT_FIXED + D;

    float *T = scratch;                           /* [TILE_PIX] transmittance behind */
    float *S_d = T + TILE_PIX;                    /* [TILE_PIX] depth composited behind */
    float *S = S_d + TILE_PIX;                    /* [TILE_PIX][D] channels behind */
    int32_t *last = (int32_t *)(S + (size_t)TILE_PIX * D);
    float *restrict v_col = (float *)(last + TILE_PIX); /* [D] */

    const float *bg = r->background;
    int32_t max_last = 0;
    for (int py = ty0; py <= ty1; py++)
        for (int px = tx0; px <= tx1; px++) {
            const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
            const size_t pix = (size_t)py * W + px;
            T[p] = r->final_T[pix];
            S_d[p] = 0.f;
            for (int c = 0; c < D; c++) S[(size_t)p * D + c] = T[p] * bg[c];
            last[p] = r->n_contrib[pix];
            if (last[p] > max_last) max_last = last[p];
        }

    const uint32_t start = r->tile_start[tile], end = r->tile_start[tile + 1];
    /* Gaussians behind every pixel's last contributor get zero from this tile. */
    for (uint32_t j = start + (uint32_t)max_last; j < end; j++)
        memset(r->slots + (size_t)r->tile_slot[j] * stride, 0, (size_t)stride * sizeof(float));

    const float *colors = r->in.colors;
    const float *v_image = gin->v_image, *v_depth = gin->v_depth, *v_alpha = gin->v_alpha;
    for (uint32_t j = start + (uint32_t)max_last; j-- > start;) {
        const cpu_gauss *rec = r->tile_rec + j;
        const int32_t g = rec->g;
        const int32_t *b = rec->box;
        const int x0 = b[0] > tx0 ? b[0] : tx0, x1 = b[1] < tx1 ? b[1] : tx1;
        const int y0 = b[2] > ty0 ? b[2] : ty0, y1 = b[3] < ty1 ? b[3] : ty1;
        const float mx = rec->mx, my = rec->my;
        const float con[3] = {rec->con[0], rec->con[1], rec->con[2]};
        const float op = rec->op, z = rec->z, cut = rec->cut, det_con = rec->det_con;
        const float *restrict col = colors + (size_t)g * D;
        const int32_t pos = (int32_t)(j - start); /* contributes where pos < last[p] */
        float v_m2[2] = {0.f, 0.f}, v_con[3] = {0.f, 0.f, 0.f}, v_op = 0.f, v_z = 0.f;
        for (int c = 0; c < D; c++) v_col[c] = 0.f;
        for (int py = y0; py <= y1; py++) {
            const float dy = (float)py + 0.5f - my;
            int rx0, rx1;
            cpu_row_range(con, det_con, cut, mx, dy, x0, x1, &rx0, &rx1);
            for (int px = rx0; px <= rx1; px++) {
                const int p = (py - ty0) * SP_TILE_SIZE + (px - tx0);
                if (pos >= last[p]) continue;
                const float dx = (float)px + 0.5f - mx;
                float gauss;
                const float alpha = sp_gm_alpha_g(con, op, cut, dx, dy, &gauss);
                if (alpha == 0.f) continue;
                const size_t pix = (size_t)py * W + px;
                const float ra = 1.f / (1.f - alpha);
                const float Ti = T[p] * ra;
                const float w = alpha * Ti;
                const float *restrict vi = v_image + pix * D;
                float *restrict Sp = S + (size_t)p * D;
                /* dC/dalpha . v = sum_c v_c (Ti c_c - S_c ra), as two dot products in four
                 * fixed lanes (vectorisable, and the same order on every run) */
                float dc[4] = {0.f, 0.f, 0.f, 0.f}, ds[4] = {0.f, 0.f, 0.f, 0.f};
                int c = 0;
                for (; c + 4 <= D; c += 4)
                    for (int l = 0; l < 4; l++) {
                        dc[l] += vi[c + l] * col[c + l];
                        ds[l] += vi[c + l] * Sp[c + l];
                    }
                for (; c < D; c++) {
                    dc[0] += vi[c] * col[c];
                    ds[0] += vi[c] * Sp[c];
                }
                float v_a = Ti * ((dc[0] + dc[1]) + (dc[2] + dc[3])) -
                            ra * ((ds[0] + ds[1]) + (ds[2] + ds[3]));
                for (int k = 0; k < D; k++) {
                    v_col[k] += w * vi[k];
                    Sp[k] += w * col[k];
                }
                if (v_depth) {
                    const float vd = v_depth[pix];
                    v_z += w * vd;
                    v_a += vd * (Ti * z - S_d[p] * ra);
                }
                if (v_alpha) v_a += v_alpha[pix] * r->final_T[pix] * ra;
                S_d[p] += w * z;
                T[p] = Ti;
                /* sp_gm_alpha_vjp inlined, reusing gauss = exp(-sigma); no gradient where
                 * alpha was capped */
                if (op * gauss <= SP_ALPHA_MAX) {
                    v_op += gauss * v_a;
                    const float v_sigma = -op * gauss * v_a;
                    const float hs = 0.5f * v_sigma;
                    v_con[0] += hs * dx * dx;
                    v_con[1] += hs * dx * dy;
                    v_con[2] += hs * dy * dy;
                    v_m2[0] -= v_sigma * (con[0] * dx + con[1] * dy);
                    v_m2[1] -= v_sigma * (con[1] * dx + con[2] * dy);
                }
            }
        }
        float *s = r->slots + (size_t)r->tile_slot[j] * stride;
        s[0] = v_m2[0];
        s[1] = v_m2[1];
        s[2] = v_con[0];
        s[3] = v_con[1];
        s[4] = v_con[2];
        s[5] = v_op;
        s[6] = v_z;
        for (int c = 0; c < D; c++) s[SP_SLOT_FIXED + c] = v_col[c];
    }
}

static void backward_item(void *vctx, long tile, int thread_id)
{
    bwd_ctx *c = vctx;
    cpu_raster *r = c->r;
    float *scratch = r->scratch[thread_id].buf;
    switch (r->D) {
    case 1: tile_backward(r, c->gin, tile, scratch, 1); break;
    case 3: tile_backward(r, c->gin, tile, scratch, 3); break;
    case 4: tile_backward(r, c->gin, tile, scratch, 4); break;
    case 8: tile_backward(r, c->gin, tile, scratch, 8); break;
    case 16: tile_backward(r, c->gin, tile, scratch, 16); break;
    case 32: tile_backward(r, c->gin, tile, scratch, 32); break;
    default: tile_backward(r, c->gin, tile, scratch, r->D); break;
    }
}

int cpu_rasterize_backward(cpu_raster *r, const sp_raster_grad_in *gin, sp_error *err)
{
    size_t stride = SP_SLOT_FIXED + (size_t)r->D;
    if (r->pairs > SIZE_MAX / sizeof(float) / stride)
        return sp_error_set(err, SP_E_NOMEM, "rasterizer backward: %zu pairs x %zu floats overflow",
                            r->pairs, stride);
    int rc = sp_scratch_reserve(r->dev, &r->slot_buf, &r->slot_cap,
                                r->pairs * stride * sizeof(float) + 64, err);
    if (rc) return rc;
    r->slots = r->slot_buf;
    rc = cpu_reserve_thread_scratch(r, err);
    if (rc) return rc;
    bwd_ctx c = {r, gin};
    sp_pool_for(r->dev->pool, (long)r->tiles_x * r->tiles_y, backward_item, &c);
    return 0;
}
